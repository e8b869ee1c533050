// Friction laws of the seed paper: hand calculations, reference values, limits, continuity,
// symmetry (../shared/reference/known_values.md for the film thickness).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "kegel/core/tribology.hpp"

namespace tr = kegel::tribology;

namespace {
constexpr double kPi = 3.14159265358979323846;

// d ln f / d ln x by central differences
template <class F>
double log_slope(F f, double x, double rel = 1e-4) {
  return (std::log(f(x * (1 + rel))) - std::log(f(x * (1 - rel)))) /
         (std::log1p(rel) - std::log1p(-rel));
}
}  // namespace

// --- Moes line contact vs known_values.md ------------------------------------------------------
TEST(Film, MoesMatchesKnownValues) {
  const double eta0 = 0.0525, R = 7.5e-3, w = 68e3, alpha = 21e-9, E = 230.8e9;
  struct Row { double u_m, moes_um, dowson_toyoda_um; };
  for (const Row& r : {Row{1.5, 0.537, 0.536}, Row{5.9, 1.371, 1.379}, Row{11.8, 2.194, 2.225}}) {
    SCOPED_TRACE(r.u_m);
    const double h = tr::moes_line_film_thickness_m(eta0, 2.0 * r.u_m, R, w, alpha, E) * 1e6;
    EXPECT_NEAR(h, r.moes_um, 5e-3 * r.moes_um);
    EXPECT_NEAR(h, r.dowson_toyoda_um, 2e-2 * r.dowson_toyoda_um);
  }
}

TEST(Film, MoesTrendsAndSpeedExponent) {
  const double eta0 = 0.0525, R = 7.5e-3, w = 68e3, alpha = 21e-9, E = 230.8e9;
  auto h_of_u = [&](double u) { return tr::moes_line_film_thickness_m(eta0, u, R, w, alpha, E); };
  auto h_of_w = [&](double ww) { return tr::moes_line_film_thickness_m(eta0, 6.0, R, ww, alpha, E); };
  // EHL regime: film grows with speed roughly as u^0.7, falls weakly with load (~ w^-0.1..-0.2)
  const double su = log_slope(h_of_u, 6.0);
  EXPECT_GT(su, 0.6);
  EXPECT_LT(su, 0.75);
  const double sw = log_slope(h_of_w, 68e3);
  EXPECT_LT(sw, 0.0);
  EXPECT_GT(sw, -0.25);
}

TEST(Film, EllipticHandCalculation) {
  const double eta0 = 0.0525, u = 2.0, Rx = 0.01, Ry = 0.2, Q = 500.0, alpha = 21e-9, E = 230.8e9;
  const double U = eta0 * u / (E * Rx), G = alpha * E, W = Q / (E * Rx * Rx);
  const double k = 1.0339 * std::pow(Ry / Rx, 0.636);
  const double ref = 2.69 * Rx * std::pow(U, 0.67) * std::pow(G, 0.53) * std::pow(W, -0.067) *
                     (1 - 0.61 * std::exp(-0.73 * k));
  // the code forms the three powers as one exponential of their logarithms: equal to rounding
  EXPECT_NEAR(tr::elliptic_film_thickness_m(eta0, u, Rx, Ry, Q, alpha, E), ref, 1e-13 * ref);
  EXPECT_NEAR(tr::ellipticity(1.0, 1.0), 1.0339, 1e-12);
}

// --- Zhu-Cheng thermal factor -----------------------------------------------------------------
TEST(Film, ZhuChengFactorInUnitIntervalAndDecreasing) {
  const double E = 230.8e9, lambda = 0.134, deta = -2.4e-3;  // FVA3 near 50 degC
  EXPECT_DOUBLE_EQ(tr::zhu_cheng_factor(1e9, E, 0.0, 10.0, 0.0, 5.0, lambda), 1.0);
  double last = 1.0 + 1e-12;
  for (double u = 0.5; u <= 40.0; u *= 1.5) {
    const double phi = tr::zhu_cheng_factor(1e9, E, 0.0, 2 * u, deta, u, lambda);
    EXPECT_GT(phi, 0.0);
    EXPECT_LE(phi, 1.0);
    EXPECT_LT(phi, last);  // more heating at higher speed
    last = phi;
  }
  // slip reduces the factor further
  EXPECT_LT(tr::zhu_cheng_factor(1e9, E, 1.0, 10.0, deta, 5.0, lambda),
            tr::zhu_cheng_factor(1e9, E, 0.0, 10.0, deta, 5.0, lambda));
  // far outside the fit's range the factor stays at its floor, never <= 0
  EXPECT_DOUBLE_EQ(tr::zhu_cheng_factor(3e9, E, 5.0, 200.0, -1.0, 100.0, lambda), tr::kZhuChengFloor);
}

TEST(Film, ZhuChengHandCalculation) {
  const double p0 = 1.2e9, E = 230.8e9, ur = 0.3, us = 10.0, deta = -2.4e-3, uav = 5.0, lam = 0.134;
  const double s = 2 * ur / us, G = 2.4e-3 * uav * uav / lam;
  const double ref = (1 - 13.2 * p0 / E * std::pow(G, 0.42)) /
                     (1 + 0.213 * (1 + 2.23 * std::pow(s, 0.83)) * std::pow(G, 0.64));
  EXPECT_NEAR(tr::zhu_cheng_factor(p0, E, ur, us, deta, uav, lam), ref, 1e-14);
}

// --- Lubricant helpers --------------------------------------------------------------------------
TEST(Lubricant, VogelDerivativeMatchesFiniteDifference) {
  const double K = 0.062e-3, B = 1021.7, C = 101.5517;
  auto eta = [&](double th) { return K * std::exp(B / (th + C)); };
  for (double th : {20.0, 50.0, 100.0}) {
    const double fd = (eta(th + 1e-4) - eta(th - 1e-4)) / 2e-4;
    EXPECT_NEAR(tr::vogel_viscosity_derivative_Pas_per_K(K, B, C, th), fd, 1e-6 * std::abs(fd));
  }
}

TEST(Lubricant, GoldCompressionTemperatureSolvesItsQuadratic) {
  const double T0 = 323.15, C1 = 2.0e3, C2 = 7.0e6;
  EXPECT_DOUBLE_EQ(tr::gold_compression_temperature_K(T0, 0.0, C1, C2), T0);
  for (double p : {1e6, 1e8, 1e9, 2e9}) {
    const double dT = tr::gold_compression_temperature_K(T0, p, C1, C2) - T0;
    EXPECT_NEAR(C1 * dT * dT + C2 * dT, p, 1e-10 * p);
  }
  // linear limit: dT ~ p / C2
  EXPECT_NEAR(tr::gold_compression_temperature_K(T0, 1e3, C1, C2) - T0, 1e3 / C2, 1e-7 * 1e3 / C2);
}

// --- Film parameter and asperity load ratio ---------------------------------------------------
TEST(Mixed, AsperityLoadRatioLimitsAndMonotonic) {
  EXPECT_DOUBLE_EQ(tr::asperity_load_ratio(0.0, 2.32, 0.97), 1.0);
  double last = 1.0;
  for (double L = 0.1; L < 10; L += 0.1) {
    const double phi = tr::asperity_load_ratio(L, 2.32, 0.97);
    EXPECT_GE(phi, 0.0);
    EXPECT_LE(phi, 1.0);
    EXPECT_LT(phi, last);
    last = phi;
  }
  EXPECT_NEAR(tr::asperity_load_ratio(1.0, 2.32, 0.97), std::exp(-2.32), 1e-15);
  EXPECT_DOUBLE_EQ(tr::film_parameter(0.32e-6, 0.16e-6), 2.0);
  EXPECT_DOUBLE_EQ(tr::mixed_friction(0.0, 5.0, 2.0), 2.0);
  EXPECT_DOUBLE_EQ(tr::mixed_friction(1.0, 5.0, 2.0), 5.0);
  EXPECT_DOUBLE_EQ(tr::mixed_friction(0.25, 5.0, 1.0), 2.0);
}

// --- Bair-Winer ----------------------------------------------------------------------------------
TEST(Traction, BairWinerNewtonianLimitSaturationAndOddness) {
  const double eta = 100.0, h = 0.5e-6, tauL = 30e6;
  // small shear rate: Newtonian tau = eta * u / h
  const double u_small = 1e-9;
  EXPECT_NEAR(tr::bair_winer_shear_stress_Pa(eta, u_small, h, tauL), eta * u_small / h,
              1e-5 * eta * u_small / h);
  // saturates at tau_L and never exceeds it
  double last = 0.0;
  for (double u = 1e-6; u < 10.0; u *= 2) {
    const double tau = tr::bair_winer_shear_stress_Pa(eta, u, h, tauL);
    EXPECT_LE(tau, tauL);
    EXPECT_GE(tau, last);
    last = tau;
  }
  EXPECT_NEAR(last, tauL, 1e-9 * tauL);
  EXPECT_DOUBLE_EQ(tr::bair_winer_shear_stress_Pa(eta, -0.01, h, tauL),
                   -tr::bair_winer_shear_stress_Pa(eta, 0.01, h, tauL));
  EXPECT_DOUBLE_EQ(tr::bair_winer_shear_stress_Pa(eta, 0.0, h, tauL), 0.0);
  EXPECT_DOUBLE_EQ(tr::limiting_shear_stress_Pa(1e6, 0.06, 1e9), 61e6);
}

// --- Biboulet-Houpert ---------------------------------------------------------------------------
// Part 1 (line contacts), Eq. 40-42: f_l = E' R F~(U, W), U = 2 eta0 u_m/(E' R), W = w/(E' R).
// Reference values: ../shared/reference/known_values.md (independent of kegel), tolerance 0.5 %.
TEST(Rolling, BibouletHoupertKnownValues) {
  const double E = 230.8e9, R = 7.5e-3, eta0 = 0.0525, L = 1e-3;
  struct Row { double u_m, w, U, W, M, f, ivr, ehl, printed; };
  const Row rows[] = {
      {1.5, 68000, 9.099e-11, 3.928e-5, 4.118, 75.11, 147.0, 74.96, 0.232},
      {5.9, 68000, 3.579e-10, 3.928e-5, 2.077, 209.1, 291.4, 209.4, 0.912},
      {11.8, 68000, 7.158e-10, 3.928e-5, 1.468, 346.2, 412.2, 352.1, 1.824},
      {5.9, 2000, 3.579e-10, 1.155e-6, 0.0611, 50.06, 49.98, 209.4, 0.912},
      {1.5, 500, 9.099e-11, 2.889e-7, 0.0303, 12.62, 12.60, 74.96, 0.232},
  };
  for (const Row& r : rows) {
    const double U = 2.0 * eta0 * r.u_m / (E * R), W = r.w / (E * R);
    EXPECT_NEAR(U, r.U, 5e-3 * r.U);
    EXPECT_NEAR(W, r.W, 5e-3 * r.W);
    EXPECT_NEAR(W / std::sqrt(U), r.M, 5e-3 * r.M);
    const double f = tr::biboulet_houpert_rolling_force_N(eta0, r.u_m, R, L, r.w * L, E) / L;
    EXPECT_NEAR(f, r.f, 5e-3 * r.f) << "u_m " << r.u_m << " w " << r.w;
    EXPECT_NEAR(E * R * tr::biboulet_houpert_line_force_ivr(U, W), r.ivr, 5e-3 * r.ivr);
    EXPECT_NEAR(E * R * tr::biboulet_houpert_line_force_ehl(U), r.ehl, 5e-3 * r.ehl);
    // the blend stays at or below the lower asymptote (within 2 % where they cross)
    EXPECT_LE(f, 1.02 * E * R * std::min(tr::biboulet_houpert_line_force_ivr(U, W), tr::biboulet_houpert_line_force_ehl(U)));
    // the seed's Eq. 16 as printed is 80-300 times smaller in the loaded (EHL) rows
    if (r.M > 1.0) EXPECT_GT(f / r.printed, 80.0);
  }
}

TEST(Rolling, BibouletHoupertAsymptotesAndExponents) {
  // M -> 0 (light load): F~ -> (1.4/c) sqrt(U W); M -> infinity: F~ -> (1.45/c) U^(3/4)
  const double U = 1e-10;
  for (double M : {1e-4, 1e-3}) {
    const double W = M * std::sqrt(U);
    EXPECT_NEAR(tr::biboulet_houpert_line_force(U, W) / tr::biboulet_houpert_line_force_ivr(U, W), 1.0, 1e-6);
  }
  for (double M : {1e3, 1e4}) {
    const double W = M * std::sqrt(U);
    EXPECT_NEAR(tr::biboulet_houpert_line_force(U, W) / tr::biboulet_houpert_line_force_ehl(U), 1.0, 1e-6);
  }
  // exponents: U^1/2 W^1/2 at light load, U^3/4 W^0 at heavy load
  const double E = 230.8e9, R = 7.5e-3, L = 1e-3;
  auto F = [&](double eta0, double u, double Q) { return tr::biboulet_houpert_rolling_force_N(eta0, u, R, L, Q, E); };
  EXPECT_NEAR(log_slope([&](double u) { return F(10.0, u, 0.01); }, 50.0), 0.5, 1e-3);
  EXPECT_NEAR(log_slope([&](double q) { return F(10.0, 50.0, q); }, 0.01), 0.5, 1e-3);
  EXPECT_NEAR(log_slope([&](double u) { return F(0.01, u, 2000.0); }, 0.1), 0.75, 1e-3);
  EXPECT_NEAR(log_slope([&](double q) { return F(0.01, 0.1, q); }, 2000.0), 0.0, 1e-3);
  // c = 4 / (8/pi)^1.5
  EXPECT_NEAR(tr::kBibouletHoupertC, 4.0 / std::pow(8.0 / kPi, 1.5), 1e-15);
}

// --- Thermal and starvation factors of the rolling force ----------------------------------------
TEST(Rolling, AiharaThermalFactorHandValues) {
  // phi_T = 1 / (1 + 0.29 L^0.78) (Aihara 1987, Eq. 21)
  EXPECT_DOUBLE_EQ(tr::aihara_thermal_factor(0.0), 1.0);
  EXPECT_NEAR(tr::aihara_thermal_factor(1.0), 1.0 / 1.29, 1e-12);                // 0.775194
  EXPECT_NEAR(tr::aihara_thermal_factor(10.0), 0.363977, 1e-6);                  // 10^0.78 = 6.02560
  for (double L = 0.0; L < 50.0; L += 0.5) EXPECT_GT(tr::aihara_thermal_factor(L), tr::aihara_thermal_factor(L + 0.5));
  // L = |d eta/d theta| u^2 / k: 2e-3 Pa s/K, 5 m/s, 0.13 W/(m K) -> 0.3846
  EXPECT_NEAR(tr::thermal_loading_parameter(-2e-3, 5.0, 0.13), 2e-3 * 25.0 / 0.13, 1e-15);
}

TEST(Rolling, BibouletHoupertStarvationFactorHandValues) {
  // Part 1, Eq. 44: (S^2 + 162.8 S) / (S^2 + 193.1 S + 1257)
  EXPECT_DOUBLE_EQ(tr::biboulet_houpert_starvation_factor(0.0), 1.0);            // fully flooded
  EXPECT_NEAR(tr::biboulet_houpert_starvation_factor(2.0), 329.6 / 1647.2, 1e-12);
  EXPECT_NEAR(tr::biboulet_houpert_starvation_factor(1.0), 329.6 / 1647.2, 1e-12);  // clamped to S = 2
  EXPECT_NEAR(tr::biboulet_houpert_starvation_factor(100.0), 26280.0 / 30567.0, 1e-12);
  EXPECT_NEAR(tr::biboulet_houpert_starvation_factor(1e7), 1.0, 1e-5);
  for (double S = 2.0; S < 500.0; S *= 1.5)
    EXPECT_LT(tr::biboulet_houpert_starvation_factor(S), tr::biboulet_houpert_starvation_factor(1.5 * S));
}

// --- Solid rolling, hysteresis ------------------------------------------------------------------
TEST(Rolling, SolidRollingAndHysteresisHandValues) {
  EXPECT_DOUBLE_EQ(tr::solid_rolling_moment_Nm(2e-5, 1.5, 400.0), 2e-5 * 8000.0);
  EXPECT_DOUBLE_EQ(tr::solid_rolling_moment_Nm(2e-5, 1.5, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(tr::hysteresis_moment_Nm(1000.0, 0.007, 1e-4), 1000.0 * 0.007 * 2e-4 / (3 * kPi));
}

// --- Cubic mu(v) --------------------------------------------------------------------------------
TEST(Coulomb, CubicLawValuesContinuityOddnessSmoothness) {
  const tr::CubicFrictionLaw law{0.12, 0.08, 0.01, 0.05};
  auto mu = [&](double v) { return tr::cubic_friction_coefficient(law, v); };
  EXPECT_DOUBLE_EQ(mu(0.0), 0.0);
  EXPECT_NEAR(mu(law.v_s_m_s), law.mu_s, 1e-15);
  EXPECT_NEAR(mu(law.v_d_m_s), law.mu_d, 1e-15);
  EXPECT_DOUBLE_EQ(mu(1.0), law.mu_d);
  const double eps = 1e-12;
  for (double v : {law.v_s_m_s, law.v_d_m_s}) {
    EXPECT_NEAR(mu(v - eps), mu(v + eps), 1e-9) << "continuity at " << v;
    // C1: one-sided slopes agree (both zero for the smoothstep)
    const double h = 1e-7;
    EXPECT_NEAR((mu(v) - mu(v - h)) / h, (mu(v + h) - mu(v)) / h, 1e-3) << "slope at " << v;
  }
  for (double v = -0.2; v <= 0.2; v += 0.0013) EXPECT_DOUBLE_EQ(mu(-v), -mu(v));
  // rises monotonically to mu_s, then falls monotonically to mu_d
  for (double v = 0.0; v + 1e-4 <= law.v_s_m_s; v += 1e-4) EXPECT_LE(mu(v), mu(v + 1e-4) + 1e-15);
  for (double v = law.v_s_m_s; v + 1e-4 <= law.v_d_m_s; v += 1e-4) EXPECT_GE(mu(v), mu(v + 1e-4) - 1e-15);
  // hand value inside the first branch: v = v_s/2 -> delta = 3/4 -> -mu_s + 2 mu_s (9/16)(3/2)
  EXPECT_NEAR(mu(0.005), -0.12 + 2 * 0.12 * 0.5625 * 1.5, 1e-15);
}

// --- Damping ------------------------------------------------------------------------------------
TEST(Damping, CubicRiseContinuousAtBothEnds) {
  const double dmax = 500.0, dm = 1e-6;
  EXPECT_DOUBLE_EQ(tr::damping_coefficient(-1e-9, dmax, dm), 0.0);
  EXPECT_NEAR(tr::damping_coefficient(1e-18, dmax, dm), 0.0, 1e-9);
  EXPECT_NEAR(tr::damping_coefficient(dm * (1 - 1e-12), dmax, dm), dmax, 1e-6);
  EXPECT_DOUBLE_EQ(tr::damping_coefficient(2 * dm, dmax, dm), dmax);
  EXPECT_DOUBLE_EQ(tr::damping_coefficient(0.5 * dm, dmax, dm), 0.5 * dmax);
  // Eq. 3 as printed
  const double d = 0.3 * dm;
  EXPECT_NEAR(tr::damping_coefficient(d, dmax, dm),
              -2 * dmax / (dm * dm * dm) * d * d * d + 3 * dmax / (dm * dm) * d * d, 1e-9);
  EXPECT_DOUBLE_EQ(tr::damping_force_N(0.2, 2 * dm, dmax, dm), -100.0);  // opposes the motion
}

TEST(Coulomb, CageFrictionIsNormalForceTimesMu) {
  const tr::CubicFrictionLaw law{0.1, 0.1, 1e-3, 2e-3};
  EXPECT_DOUBLE_EQ(tr::cage_friction_force_N(law, 20.0, 0.5), 2.0);
  EXPECT_DOUBLE_EQ(tr::cage_friction_force_N(law, 20.0, -0.5), -2.0);
  EXPECT_DOUBLE_EQ(tr::cage_friction_force_N(law, 20.0, 0.0), 0.0);
}
