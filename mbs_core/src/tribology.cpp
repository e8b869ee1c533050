#include "kegel/core/tribology.hpp"

#include <algorithm>
#include <cmath>

namespace kegel::tribology {

double moes_line_film_thickness_m(double eta0, double u_sum, double R, double w, double alpha,
                                  double E) noexcept {
  // Dimensionless groups of Moes (Venner-Lubrecht form, ../shared/reference/known_values.md).
  const double U = eta0 * u_sum / (E * R);
  const double W = w / (E * R);
  const double G = alpha * E;
  const double M = W / std::sqrt(U);
  const double L = G * std::pow(U, 0.25);
  const double H_RI = 3.0 / M;                                    // rigid-isoviscous
  const double H_EI = 2.621 * std::pow(M, -0.2);                  // elastic-isoviscous
  const double H_RP = 1.287 * std::pow(L, 2.0 / 3.0);             // rigid-piezoviscous
  const double H_EP = 1.311 * std::pow(M, -0.125) * std::pow(L, 0.75);  // elastic-piezoviscous
  const double s = (7.0 + 8.0 * std::exp(-2.0 * H_EI / H_RI)) / 5.0;
  const double iso = std::pow(std::pow(H_RI, 7.0 / 3.0) + std::pow(H_EI, 7.0 / 3.0), 3.0 * s / 7.0);
  const double piezo = std::pow(std::pow(H_RP, -3.5) + std::pow(H_EP, -3.5), -2.0 * s / 7.0);
  const double H = std::pow(iso + piezo, 1.0 / s);
  return H * R * std::sqrt(U);
}

double elliptic_film_thickness_m(double eta0, double u_av, double Rx, double Ry, double Q,
                                 double alpha, double E) noexcept {
  const double U = eta0 * u_av / (E * Rx);   // Eq. 33
  const double G = alpha * E;                // Eq. 34
  const double W = Q / (E * Rx * Rx);        // Eq. 35
  const double k = ellipticity(Rx, Ry);      // Eq. 32
  return 2.69 * Rx * std::pow(U, 0.67) * std::pow(G, 0.53) * std::pow(W, -0.067) *
         (1.0 - 0.61 * std::exp(-0.73 * k));  // Eq. 31
}

double zhu_cheng_factor(double p0, double E, double u_rel, double u_sum, double deta_dtheta,
                        double u_av, double lambda) noexcept {
  const double s = u_sum > 0.0 ? 2.0 * std::abs(u_rel) / u_sum : 0.0;  // Eq. 13
  const double Gamma = std::abs(deta_dtheta) * u_av * u_av / lambda;   // Eq. 14
  const double num = 1.0 - 13.2 * (p0 / E) * std::pow(Gamma, 0.42);
  const double den = 1.0 + 0.213 * (1.0 + 2.23 * std::pow(s, 0.83)) * std::pow(Gamma, 0.64);
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
