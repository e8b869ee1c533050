#include "kegel/core/tribology.hpp"

#include <algorithm>
#include <cmath>

namespace kegel::tribology {

double moes_line_film_thickness_m(double eta0, double u_sum, double R, double w, double alpha,
                                  double E) noexcept {
  // Dimensionless groups of Moes (Venner-Lubrecht form, ../shared/reference/known_values.md),
  // evaluated in logarithms: the powers of M and L and the blend's exponents share three
  // logarithms (12 calls of pow cost 14 % of a warm quasi-static point; the same formula)
  //   U = eta0 u_sum / (E R), W = w / (E R), G = alpha E, M = W / sqrt(U), L = G U^(1/4)
  //   H_RI = 3 / M, H_EI = 2.621 M^(-1/5), H_RP = 1.287 L^(2/3), H_EP = 1.311 M^(-1/8) L^(3/4)
  //   s = (7 + 8 exp(-2 H_EI / H_RI)) / 5
  //   H = ((H_RI^(7/3) + H_EI^(7/3))^(3 s / 7) + (H_RP^(-7/2) + H_EP^(-7/2))^(-2 s / 7))^(1 / s)
  //   h = H R sqrt(U)
  const double lnU = std::log(eta0 * u_sum / (E * R));
  const double lnM = std::log(w / (E * R)) - 0.5 * lnU;
  const double lnL = std::log(alpha * E) + 0.25 * lnU;
  constexpr double ln3 = 1.0986122886681098, ln2621 = 0.9635559243412692;   // log 3, log 2.621
  constexpr double ln1287 = 0.25231392861398955, ln1311 = 0.27079020478156274;  // log 1.287, log 1.311
  const double lnH_RI = ln3 - lnM;
  const double lnH_EI = ln2621 - 0.2 * lnM;
  const double lnH_RP = ln1287 + (2.0 / 3.0) * lnL;
  const double lnH_EP = ln1311 - 0.125 * lnM + 0.75 * lnL;
  const double s = (7.0 + 8.0 * std::exp(-2.0 * std::exp(lnH_EI - lnH_RI))) / 5.0;
  const double iso = std::exp((3.0 * s / 7.0) *
                              std::log(std::exp((7.0 / 3.0) * lnH_RI) + std::exp((7.0 / 3.0) * lnH_EI)));
  const double piezo = std::exp((-2.0 * s / 7.0) * std::log(std::exp(-3.5 * lnH_RP) + std::exp(-3.5 * lnH_EP)));
  return R * std::exp(std::log(iso + piezo) / s + 0.5 * lnU);
}

double elliptic_film_thickness_m(double eta0, double u_av, double Rx, double Ry, double Q,
                                 double alpha, double E) noexcept {
  const double U = eta0 * u_av / (E * Rx);   // Eq. 33
  const double G = alpha * E;                // Eq. 34
  const double W = Q / (E * Rx * Rx);        // Eq. 35
  const double k = ellipticity(Rx, Ry);      // Eq. 32
  // Eq. 31, the three powers as one exponential of their logarithms (the rib cells call this
  // for every cell in every friction evaluation)
  return 2.69 * Rx * std::exp(0.67 * std::log(U) + 0.53 * std::log(G) - 0.067 * std::log(W)) *
         (1.0 - 0.61 * std::exp(-0.73 * k));
}

double zhu_cheng_factor(double p0, double E, double u_rel, double u_sum, double deta_dtheta,
                        double u_av, double lambda) noexcept {
  const double s = u_sum > 0.0 ? 2.0 * std::abs(u_rel) / u_sum : 0.0;  // Eq. 13
  const double Gamma = std::abs(deta_dtheta) * u_av * u_av / lambda;   // Eq. 14
  // Gamma^0.42 and Gamma^0.64 from one logarithm (log 0 = -inf gives exp(-inf) = 0, as pow)
  const double lnGamma = std::log(Gamma);
  const double num = 1.0 - 13.2 * (p0 / E) * std::exp(0.42 * lnGamma);
  const double den = 1.0 + 0.213 * (1.0 + 2.23 * std::pow(s, 0.83)) * std::exp(0.64 * lnGamma);
  return std::clamp(num / den, kZhuChengFloor, 1.0);  // Eq. 12
}

double biboulet_houpert_line_force(double U, double W) noexcept {
  const double M = W / std::sqrt(U);                       // Moes load parameter
  const double x = (1.4 / 1.45) * std::sqrt(M);
  const double x2 = x * x, x10 = x2 * x2 * x2 * x2 * x2;
  return 1.4 * std::sqrt(U * W) / (kBibouletHoupertC * std::pow(1.0 + x10, 0.1));
}

double biboulet_houpert_rolling_force_N(double eta0, double u_m, double R, double L, double Q,
                                        double E) noexcept {
  const double U = 2.0 * eta0 * u_m / (E * R);  // Biboulet-Houpert's U (factor 2)
  const double W = Q / (L * E * R);
  return E * R * L * biboulet_houpert_line_force(U, W);
}

}  // namespace kegel::tribology
