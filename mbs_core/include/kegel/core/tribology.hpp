// Contact friction laws of the seed paper (Wingertszahn et al., Lubricants 2023, 11, 369,
// Section 2.1.2-2.1.3), each a small free function in SI units.
//
// All functions are noexcept and allocation-free: they run per slice and per cell in the hot
// loop. They do not validate their arguments; callers check inputs at the boundary (scene,
// data files, Python bindings). Where a law is odd in a velocity, the sign is kept explicitly.
#pragma once

#include <cmath>

namespace kegel::tribology {

// ---------------------------------------------------------------------------------------------
// Lubricant
// ---------------------------------------------------------------------------------------------

/// Eq. 15: temperature derivative of the Vogel viscosity, d eta / d theta [Pa s / K], with the
/// Vogel parameters K [Pa s], B [K] and C [degC] of Eq. 8 (A_V, B_V, C_V in the paper's Eq. 15).
inline double vogel_viscosity_derivative_Pas_per_K(double K_Pas, double B_K, double C_degC,
                                                    double theta_degC) noexcept {
  const double s = theta_degC + C_degC;
  return -B_K / (s * s) * K_Pas * std::exp(B_K / s);
}

/// Eq. 9 (Gold et al.): lubricant temperature after compression heating to pressure p,
/// T = T0 - C2/(2 C1) + sqrt((C2/(2 C1))^2 + p/C1), i.e. the root of
/// p = C1 (T - T0)^2 + C2 (T - T0). C1 [Pa/K^2] > 0, C2 [Pa/K] > 0.
inline double gold_compression_temperature_K(double T0_K, double p_Pa, double C1_Pa_K2,
                                             double C2_Pa_K) noexcept {
  const double h = C2_Pa_K / (2.0 * C1_Pa_K2);
  // Written as T0 + p / (C1 (h + sqrt(h^2 + p/C1))) to avoid cancellation at small p.
  return T0_K + (p_Pa / C1_Pa_K2) / (h + std::sqrt(h * h + p_Pa / C1_Pa_K2));
}

// ---------------------------------------------------------------------------------------------
// Film thickness
// ---------------------------------------------------------------------------------------------

/// Moes' central film thickness of a line contact (Moes 1992, in the form of Venner and Lubrecht 2000;
/// ../shared/reference/known_values.md; the seed's ref. [14] is Kannel and Walowit, not Moes).
///
/// @param eta0_Pas        viscosity at the inlet temperature and ambient pressure
/// @param u_sum_m_s       sum velocity u1 + u2 (twice the mean entrainment speed), > 0
/// @param R_m             reduced radius in the rolling direction
/// @param w_N_m           load per unit length
/// @param alpha_p_1_Pa    pressure-viscosity coefficient
/// @param E_reduced_Pa    E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)
/// @return central film thickness h_c [m]
double moes_line_film_thickness_m(double eta0_Pas, double u_sum_m_s, double R_m, double w_N_m,
                                  double alpha_p_1_Pa, double E_reduced_Pa) noexcept;

/// Eq. 32: ellipticity k = a/b ~ 1.0339 (Ry/Rx)^0.636.
inline double ellipticity(double Rx_m, double Ry_m) noexcept {
  return 1.0339 * std::pow(Ry_m / Rx_m, 0.636);
}

/// Eq. 31, 33-35: central film thickness of an elliptic contact (roller end / rib),
/// h0 = 2.69 Rx U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k)), with U = eta0 u_av/(E' Rx),
/// G = alpha_p E', W = Q/(E' Rx^2). (The paper prints W^-0.069; Hamrock-Dowson's published
/// exponent is -0.067, used here.)
double elliptic_film_thickness_m(double eta0_Pas, double u_av_m_s, double Rx_m, double Ry_m,
                                 double Q_N, double alpha_p_1_Pa, double E_reduced_Pa) noexcept;

/// Eq. 11-14 (Zhu and Cheng): thermal reduction factor of the film thickness,
/// phi = (1 - 13.2 (p0/E') Gamma^0.42) / (1 + 0.213 (1 + 2.23 s^0.83) Gamma^0.64),
/// s = 2 |u_rel| / u_sum (Eq. 13), Gamma = (-d eta/d theta) u_av^2 / lambda (Eq. 14).
/// The fit's numerator turns negative far outside its calibration range; the result is kept in
/// [kZhuChengFloor, 1] so that the film never vanishes or grows through this factor.
inline constexpr double kZhuChengFloor = 0.05;
double zhu_cheng_factor(double p0_Pa, double E_reduced_Pa, double u_rel_m_s, double u_sum_m_s,
                        double deta_dtheta_Pas_K, double u_av_m_s,
                        double thermal_conductivity_W_mK) noexcept;

/// Eq. 30: film parameter Lambda = h / sigma.
inline double film_parameter(double h_m, double sigma_m) noexcept { return h_m / sigma_m; }

/// Eq. 29 (Zhou and Hoeprich): asperity load ratio phi = Q_s/Q = exp(-B Lambda^C), in (0, 1].
inline double asperity_load_ratio(double Lambda, double B, double C) noexcept {
  return std::exp(-B * std::pow(Lambda > 0.0 ? Lambda : 0.0, C));
}

// ---------------------------------------------------------------------------------------------
// Friction
// ---------------------------------------------------------------------------------------------

/// Limiting shear stress, pressure-proportional form tau_L = tau_L0 + gamma_L p (see the
/// lubricant data file for the source).
inline double limiting_shear_stress_Pa(double tau_L0_Pa, double gamma_L, double p_Pa) noexcept {
  return tau_L0_Pa + gamma_L * p_Pa;
}

/// Eq. 4-6, 10 (Bair and Winer): lubricant shear stress at shear rate gamma_dot = u_rel / h.
/// Physically consistent form of Eq. 6: tau = tau_L (1 - exp(-eta |gamma_dot| / tau_L)),
/// odd in u_rel. (Eq. 6 as printed, gamma_dot = (tau_L/eta) ln(1 - tau/tau_L), has the opposite
/// sign: its right side is negative for 0 < tau < tau_L.) Newtonian for small shear rates,
/// saturating at tau_L.
inline double bair_winer_shear_stress_Pa(double eta_Pas, double u_rel_m_s, double h_m,
                                         double tau_L_Pa) noexcept {
  const double gamma_dot = std::abs(u_rel_m_s) / h_m;
  const double tau = tau_L_Pa * -std::expm1(-eta_Pas * gamma_dot / tau_L_Pa);
  return u_rel_m_s < 0.0 ? -tau : tau;
}

/// Biboulet and Houpert (Proc. IMechE J 224 (2010) 765-775, Part 1, Eq. 40-42): dimensionless
/// hydrodynamic rolling force of a line contact in pure rolling,
///   F~ = 1.4 sqrt(U W) / (c (1 + ((1.4/1.45) sqrt(M))^10)^(1/10)),  c = 4 / (8/pi)^1.5,
/// with their groups U = 2 eta0 u_m / (E' R) (u_m the mean entrainment speed, note the 2),
/// W = w / (E' R) (w the load per unit length) and the Moes load parameter M = W / sqrt(U).
/// Asymptotes: isoviscous-rigid F~ -> (1.4/c) sqrt(U W) (M -> 0) and elastic (EHL)
/// F~ -> (1.45/c) U^(3/4) (M -> infinity), independent of the load.
///
/// Seed misprint (Wingertszahn et al. 2023, Eq. 16-18): the seed defines U without the 2 and
/// writes sqrt(W/(2U)) in the blend where the source has sqrt(M) = sqrt(W / sqrt(U)). As printed
/// the EHL limit becomes 1.47 (2U) instead of 1.47 U^(3/4): linear in the speed and 80-300 times
/// too small at bearing conditions (../shared/reference/known_values.md, EHL rolling resistance).
inline constexpr double kBibouletHoupertC = 0.9843506216076513;  // 4 / (8/pi)^1.5
double biboulet_houpert_line_force(double U, double W) noexcept;
/// Isoviscous-rigid asymptote of biboulet_houpert_line_force: (1.4/c) sqrt(U W).
inline double biboulet_houpert_line_force_ivr(double U, double W) noexcept {
  return 1.4 / kBibouletHoupertC * std::sqrt(U * W);
}
/// Elastic (EHL) asymptote of biboulet_houpert_line_force: (1.45/c) U^(3/4).
inline double biboulet_houpert_line_force_ehl(double U) noexcept {
  return 1.45 / kBibouletHoupertC * std::pow(U, 0.75);
}

/// EHL rolling resistance force [N] of a line-contact slice of width L_m under the load Q_N:
/// f = E' R F~(U, W) per unit length (biboulet_houpert_line_force) times L, with
/// U = 2 eta0 u_m/(E' R) and W = Q/(L E' R). It acts on each of the two surfaces against its
/// motion relative to the contact (dissipation f (u1 + u2) = 2 f u_m in pure rolling).
double biboulet_houpert_rolling_force_N(double eta0_Pas, double u_mean_m_s, double R_m,
                                        double L_m, double Q_N, double E_reduced_Pa) noexcept;

/// Rolling force per unit length [N/m] carried by the film beyond the film height g on the inlet
/// side of a line contact: what the contact / hydraulic boundary g (model.contact_film_limit)
/// takes from Biboulet-Houpert's flooded rolling force and hands to the CFD.
///
/// Reynolds' equation in pure rolling gives dp/dx = 12 eta0 u_m (h - h_c) / h^3 and the rolling
/// force on each surface f = 1/2 int h dp/dx dx (Biboulet-Houpert Part 1, Eq. 8 and 23; Crook's
/// integral in Zhou-Hoeprich 1991, Eq. 2). Where the film is thick (h >> h_c) the pressure is
/// small, the oil isoviscous at eta0 and the surfaces rigid, so f = 6 eta0 u_m int dx / h. Over
/// Biboulet-Houpert's rigid gap h = R (1 - sqrt(1 - X^2)), X = x / R (their Eq. 7), from their
/// flooded inlet X = -1 to the point where h = g, with X = sin(theta) and G = g / R:
///
///   f = 6 eta0 u_m I(G),  I(G) = cot(theta_g / 2) + theta_g - 1 - pi/2,
///   cot(theta_g / 2) = sqrt(2 G - G^2) / G,  theta_g = 2 asin(sqrt(G / 2)),
///
/// and 0 for G >= 1 (the cut lies beyond the flooded inlet). For small G, I -> sqrt(2 / G).
/// The neglected terms are of relative order h_c / g: against the exact isoviscous-rigid solution
/// at a fixed gap h0 with the inlet meniscus moved from X = -1 to h = g (Reynolds outlet), the
/// removed force is right within 0.12 % of the flooded force at g = 100 h0, 1.0 % at 25 h0 and
/// 3.8 % at 10 h0 (too large there; tests/python/test_film_limit_law.py). Biboulet-Houpert's
/// Eq. 44, a fit over S of a starved EHL contact, removes 14 % at S = 100 where the exact
/// isoviscous-rigid cut removes 15.6 %, and its tail 30.3 / S falls faster than the far field's
/// sqrt(2 h0 / g): it is kept for the supply, not used for the cut.
inline double rolling_force_beyond_film_N_m(double eta0_Pas, double u_mean_m_s, double R_m,
                                            double g_m) noexcept {
  const double G = g_m / R_m;
  if (!(G > 0.0) || G >= 1.0) return 0.0;
  const double theta_g = 2.0 * std::asin(std::sqrt(0.5 * G));
  const double I = std::sqrt(2.0 / G - 1.0) + theta_g - 1.0 - 1.5707963267948966;
  return 6.0 * eta0_Pas * u_mean_m_s * I;
}

/// Thermal loading parameter of the inlet, L = (-d eta/d theta) u^2 / k = eta0 beta u^2 / k
/// (Murch and Wilson 1975; Aihara 1987, Eq. 20; the Gamma of the seed's Eq. 14), with u the
/// rolling (mean entrainment) speed and k the lubricant's thermal conductivity.
inline double thermal_loading_parameter(double deta_dtheta_Pas_K, double u_m_s,
                                        double thermal_conductivity_W_mK) noexcept {
  return std::abs(deta_dtheta_Pas_K) * u_m_s * u_m_s / thermal_conductivity_W_mK;
}

/// Aihara's thermal reduction of the EHL rolling force by inlet shear heating,
/// phi_T = 1 / (1 + 0.29 L^0.78) (J. Tribol. 109 (1987) 471, Eq. 21: his fit, for L from 0 to
/// several tens, of the ratio of Goksem and Hargreaves' thermal to isothermal rolling force,
/// after Murch and Wilson). Reprinted with the same constants by Manjunath et al., Machines 11
/// (2023) 801, Eq. 24.
inline double aihara_thermal_factor(double L) noexcept {
  return 1.0 / (1.0 + 0.29 * std::pow(L > 0.0 ? L : 0.0, 0.78));
}

/// Starvation of the rolling resistance, Biboulet and Houpert Part 1, Eq. 44:
/// T / T_flooded = (S^2 + 162.8 S) / (S^2 + 193.1 S + 1257), S the oil gap at the inlet meniscus
/// over the fully flooded film; computed by them down to S = 2 (S is clamped there); S <= 0
/// means fully flooded (factor 1).
inline double biboulet_houpert_starvation_factor(double S) noexcept {
  if (!(S > 0.0)) return 1.0;
  const double s = S < 2.0 ? 2.0 : S;
  return (s * s + 162.8 * s) / (s * s + 193.1 * s + 1257.0);
}

/// Eq. 19 (Scheuermann): solid rolling friction moment M = c_r F_N^e_r.
inline double solid_rolling_moment_Nm(double c_r, double e_r, double F_N) noexcept {
  return F_N > 0.0 ? c_r * std::pow(F_N, e_r) : 0.0;
}

/// Eq. 20 (Johnson): hysteresis moment M = Q a_v 2b / (3 pi), b the Hertzian half-width.
inline double hysteresis_moment_Nm(double Q_N, double a_v, double b_m) noexcept {
  constexpr double kPi = 3.14159265358979323846;
  return Q_N * a_v * 2.0 * b_m / (3.0 * kPi);
}

/// Parameters of the regularised Coulomb law mu(v) of Eq. 21-28 (and Eq. 37 for the cage).
struct CubicFrictionLaw {
  double mu_s = 0.0;   ///< peak ("static") coefficient, reached at |v| = v_s
  double mu_d = 0.0;   ///< dynamic coefficient, from |v| = v_d on
  double v_s_m_s = 0.0;
  double v_d_m_s = 0.0;
};

/// Eq. 21-27: friction coefficient mu(v), a cubic step (smoothstep) from -mu_s at -v_s to mu_s
/// at v_s, then from mu_s to mu_d between v_s and v_d, constant beyond; odd in v and C1.
/// (Eq. 21 as printed omits the factor a_cubic in front of delta^2 (3 - 2 delta).)
inline double cubic_friction_coefficient(const CubicFrictionLaw& law, double v_m_s) noexcept {
  // Evaluated at |v| and signed afterwards, so that mu(-v) = -mu(v) holds to the last bit.
  const double a = std::abs(v_m_s);
  double mu;
  if (a < law.v_s_m_s) {
    const double d = (a + law.v_s_m_s) / (2.0 * law.v_s_m_s);     // Eq. 24
    mu = -law.mu_s + 2.0 * law.mu_s * d * d * (3.0 - 2.0 * d);     // Eq. 22, 23
  } else if (a < law.v_d_m_s) {
    const double d = (a - law.v_s_m_s) / (law.v_d_m_s - law.v_s_m_s);          // Eq. 27
    mu = law.mu_s + (law.mu_d - law.mu_s) * d * d * (3.0 - 2.0 * d);          // Eq. 25, 26
  } else {
    mu = law.mu_d;
  }
  return v_m_s < 0.0 ? -mu : mu;
}

/// Eq. 37: Coulomb friction force of the roller/cage-pocket contact, F_T = F_N mu(v) with the
/// regularised mu(v) of Eq. 21-27 (odd in the sliding velocity v).
inline double cage_friction_force_N(const CubicFrictionLaw& law, double F_N, double v_m_s) noexcept {
  return F_N * cubic_friction_coefficient(law, v_m_s);
}

/// Eq. 36 (Steinert): mixed friction F = phi F_solid + (1 - phi) F_fluid.
inline double mixed_friction(double phi, double F_solid, double F_fluid) noexcept {
  return phi * F_solid + (1.0 - phi) * F_fluid;
}

/// Eq. 2-3: damping coefficient d(delta): 0 below contact, a cubic rise to d_max at delta_max
/// (zero slope at both ends), d_max beyond.
inline double damping_coefficient(double delta_m, double d_max_Ns_m, double delta_max_m) noexcept {
  if (delta_m <= 0.0) return 0.0;
  if (delta_m >= delta_max_m) return d_max_Ns_m;
  const double x = delta_m / delta_max_m;
  return d_max_Ns_m * x * x * (3.0 - 2.0 * x);  // = -2 d_max/dm^3 delta^3 + 3 d_max/dm^2 delta^2
}

/// Eq. 1: damping force along the normal, F_D = -d(delta) v_N.
inline double damping_force_N(double v_normal_m_s, double delta_m, double d_max_Ns_m,
                              double delta_max_m) noexcept {
  return -damping_coefficient(delta_m, d_max_Ns_m, delta_max_m) * v_normal_m_s;
}

}  // namespace kegel::tribology
