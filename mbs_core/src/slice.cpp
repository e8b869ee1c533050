#include "kegel/core/slice.hpp"

#include <cmath>
#include <utility>

#include "kegel/core/checks.hpp"

namespace kegel {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kPaPerBar = 1.0e5;
}  // namespace

FrictionParameters::FrictionParameters(const Values& v) : v_(v) {
  using namespace detail;
  constexpr const char* o = "FrictionParameters";
  require_nonnegative(o, "tau_L0_Pa", v.tau_L0_Pa);
  require_nonnegative(o, "gamma_L", v.gamma_L);
  if (!(v.tau_L0_Pa + v.gamma_L > 0.0)) fail(o, "gamma_L", v.gamma_L, "tau_L0_Pa + gamma_L > 0");
  require_positive(o, "mu_s", v.mu_s);
  require_positive(o, "mu_d", v.mu_d);
  require_positive(o, "v_s_m_s", v.v_s_m_s);
  if (!(std::isfinite(v.v_d_m_s) && v.v_d_m_s > v.v_s_m_s)) fail(o, "v_d_m_s", v.v_d_m_s, "a value > v_s_m_s");
  require_nonnegative(o, "c_r", v.c_r);
  require_positive(o, "e_r", v.e_r);
  require_nonnegative(o, "a_v", v.a_v);
  require_nonnegative(o, "d_max_Ns_m", v.d_max_Ns_m);
  require_positive(o, "delta_max_m", v.delta_max_m);
  require_nonnegative(o, "gold_C1_Pa_K2", v.gold_C1_Pa_K2);
  require_nonnegative(o, "gold_C2_Pa_K", v.gold_C2_Pa_K);
  if ((v.gold_C1_Pa_K2 > 0.0) != (v.gold_C2_Pa_K > 0.0)) {
    fail(o, "gold_C2_Pa_K", v.gold_C2_Pa_K, "C1 and C2 both > 0 (Eq. 9 on) or both 0 (off)");
  }
  const int rt = static_cast<int>(v.rolling_thermal);
  if (rt < 0 || rt > 2) fail(o, "rolling_thermal", rt, "0 (off), 1 (Aihara) or 2 (Zhu-Cheng)");
  for (const auto& [name, S] : {std::pair{"inlet_gap_ratio_inner", v.inlet_gap_ratio_inner},
                                std::pair{"inlet_gap_ratio_outer", v.inlet_gap_ratio_outer}}) {
    if (!(S == 0.0 || (std::isfinite(S) && S >= 2.0))) {
      fail(o, name, S, "0 (fully flooded) or a ratio >= 2 (Biboulet-Houpert's range)");
    }
  }
  if (!(v.contact_film_limit_m == 0.0 || (std::isfinite(v.contact_film_limit_m) && v.contact_film_limit_m > 0.0))) {
    fail(o, "contact_film_limit_m", v.contact_film_limit_m, "0 (no cut-off) or a film height > 0");
  }
  law_ = tribology::CubicFrictionLaw{v.mu_s, v.mu_d, v.v_s_m_s, v.v_d_m_s};
}

SurfacePair::SurfacePair(double sigma, double B, double C, double E) : sigma_(sigma), B_(B), C_(C), E_(E) {
  using namespace detail;
  require_positive("SurfacePair", "sigma_m", sigma);
  require_positive("SurfacePair", "zhou_hoeprich_B", B);
  require_positive("SurfacePair", "zhou_hoeprich_C", C);
  require_positive("SurfacePair", "E_reduced_Pa", E);
}

ContactLubricantState make_contact_lubricant_state(const Lubricant& lub, double T) {
  check_temperature(lub, T);
  const auto& q = lub.parameters();
  const double theta = T - 273.15;
  ContactLubricantState s;
  s.temperature_K = T;
  s.eta0_Pas = viscosity_ambient_Pas(lub, T);
  s.alpha_p_1_Pa = pressure_viscosity_coefficient_per_Pa(lub, T);
  s.deta_dtheta_Pas_K =
      tribology::vogel_viscosity_derivative_Pas_per_K(q.vogel_K_Pas, q.vogel_B_K, q.vogel_C_degC, theta);
  s.thermal_conductivity_W_mK = q.thermal_conductivity_W_mK;
  s.dicke_a_bar = q.dicke_a1_bar + q.dicke_a2_bar_per_K * theta;
  s.dicke_b = q.dicke_b1 + q.dicke_b2_per_K * theta;
  s.vogel_K_Pas = q.vogel_K_Pas;
  s.vogel_B_K = q.vogel_B_K;
  s.vogel_C_degC = q.vogel_C_degC;
  s.dicke_a1_bar = q.dicke_a1_bar;
  s.dicke_a2_bar_per_K = q.dicke_a2_bar_per_K;
  s.dicke_b1 = q.dicke_b1;
  s.dicke_b2_per_K = q.dicke_b2_per_K;
  if (!(s.dicke_a_bar > 0.0)) {
    detail::fail("Lubricant", "temperature_K", T, "a temperature with a1 + a2*theta > 0 (Eq. 7)");
  }
  if (s.dicke_b < 0.0) {
    detail::fail("Lubricant", "temperature_K", T,
                 "a temperature with b1 + b2*theta >= 0, so that Eq. 7 stays finite at any pressure");
  }
  return s;
}

namespace {
// Mixed sliding friction of a slice or cell whose pressure, area, film and phi are set in out:
// Dicke viscosity and limiting shear at the mean pressure (Eq. 4-7, 10) at the bulk temperature
// or, with Eq. 9 on, at the compression temperature; solid friction (Eq. 21-28); Eq. 36.
void sliding_friction(double urx, double ury, double us, double Q, const ContactLubricantState& lub,
                      const FrictionParameters& fp, SliceResult& out) noexcept {
  const auto& v = fp.values();
  const double phi = out.phi;
  const double p_bar = out.mean_pressure_Pa / kPaPerBar;
  double eta0_c = lub.eta0_Pas, a_c = lub.dicke_a_bar, b_c = lub.dicke_b;
  out.contact_temperature_K = lub.temperature_K;
  if (fp.compression_heating()) {
    const double Tc = tribology::gold_compression_temperature_K(lub.temperature_K, out.mean_pressure_Pa,
                                                                v.gold_C1_Pa_K2, v.gold_C2_Pa_K);
    const double th = Tc - 273.15;
    out.contact_temperature_K = Tc;
    eta0_c = lub.vogel_K_Pas * std::exp(lub.vogel_B_K / (th + lub.vogel_C_degC));
    a_c = lub.dicke_a1_bar + lub.dicke_a2_bar_per_K * th;
    b_c = lub.dicke_b1 + lub.dicke_b2_per_K * th;
  }
  out.eta_contact_Pas = eta0_c * std::exp(p_bar / (a_c + b_c * p_bar));
  out.tau_L_Pa = tribology::limiting_shear_stress_Pa(v.tau_L0_Pa, v.gamma_L, out.mean_pressure_Pa);
  if (out.film_m > 0.0) {
    out.tau_ehl_Pa = tribology::bair_winer_shear_stress_Pa(out.eta_contact_Pas, us, out.film_m, out.tau_L_Pa);
  }
  // Solid sliding (Eq. 21-28)
  out.mu_solid = tribology::cubic_friction_coefficient(fp.cubic_law(), us);

  // Mixed friction (Eq. 36), directed against the sliding velocity of the roller
  const double f_ehl = (1.0 - phi) * out.tau_ehl_Pa * out.area_m2;
  const double f_solid = phi * out.mu_solid * Q;
  if (us > 0.0) {
    const double ex = urx / us, ey = ury / us;
    out.F_ehl_sliding_N[0] = -f_ehl * ex;
    out.F_ehl_sliding_N[1] = -f_ehl * ey;
    out.F_solid_sliding_N[0] = -f_solid * ex;
    out.F_solid_sliding_N[1] = -f_solid * ey;
    out.P_ehl_sliding_W = f_ehl * us;
    out.P_solid_sliding_W = f_solid * us;
  }
}
}  // namespace

void evaluate_slice(const SliceInput& in, const SurfacePair& sp, const ContactLubricantState& lub,
                    const FrictionParameters& fp, SliceResult& out) noexcept {
  out = SliceResult{};
  if (!(in.load_N > 0.0) || !(in.width_m > 0.0)) return;
  out.in_contact = true;
  const auto& v = fp.values();
  const double E = sp.E_reduced_Pa();
  const double Q = in.load_N;
  const double w = Q / in.width_m;
  const double R = in.reduced_radius_m;

  // Hertz line contact of the slice (the A_Hertz of Eq. 5, the b of Eq. 20)
  const double b = std::sqrt(8.0 * w * R / (kPi * E));
  out.half_width_m = b;
  out.max_pressure_Pa = 2.0 * w / (kPi * b);
  out.mean_pressure_Pa = 0.5 * w / b;
  out.area_m2 = 2.0 * b * in.width_m;

  // Kinematics
  const double urx = in.u1_x_m_s - in.u2_x_m_s;
  const double ury = in.u1_y_m_s - in.u2_y_m_s;
  const double us = std::sqrt(urx * urx + ury * ury);  // speeds: no overflow, and hypot is slow
  const double uav = 0.5 * std::abs(in.u1_x_m_s + in.u2_x_m_s);
  out.sliding_speed_m_s = us;
  out.entrainment_speed_m_s = uav;

  // Film: Moes (line contact) with the Zhu-Cheng thermal factor (Eq. 11-14)
  if (uav > 0.0) {
    out.film_isothermal_m = tribology::moes_line_film_thickness_m(lub.eta0_Pas, 2.0 * uav, R, w,
                                                                  lub.alpha_p_1_Pa, E);
    out.thermal_factor = tribology::zhu_cheng_factor(out.max_pressure_Pa, E, us, 2.0 * uav,
                                                     lub.deta_dtheta_Pas_K, uav,
                                                     lub.thermal_conductivity_W_mK);
    out.film_m = out.thermal_factor * out.film_isothermal_m;
  }
  out.Lambda = tribology::film_parameter(out.film_m, sp.sigma_m());  // Eq. 30
  const double phi = tribology::asperity_load_ratio(out.Lambda, sp.B(), sp.C());  // Eq. 29
  out.phi = phi;

  sliding_friction(urx, ury, us, Q, lub, fp, out);

  // Rolling resistance: EHL (Biboulet-Houpert Part 1; the seed's Eq. 16-18 corrected), solid
  // (Eq. 19), hysteresis (Eq. 20)
  if (uav > 0.0) {
    switch (v.rolling_thermal) {
      case RollingThermal::Aihara:
        out.rolling_thermal_factor = tribology::aihara_thermal_factor(
            tribology::thermal_loading_parameter(lub.deta_dtheta_Pas_K, uav, lub.thermal_conductivity_W_mK));
        break;
      case RollingThermal::ZhuCheng: out.rolling_thermal_factor = out.thermal_factor; break;
      case RollingThermal::Off: out.rolling_thermal_factor = 1.0; break;
    }
    // Inlet of the rolling force: the supply's meniscus as Biboulet-Houpert's starvation
    // (Part 1, Eq. 44, S the gap at the meniscus over the flooded film). The contact / hydraulic
    // boundary g removes the rolling force the film carries between g and the supply's meniscus
    // (BH's flooded inlet X = -1 when flooded): rolling_force_beyond_film_N_m, isothermal and
    // rigid out there. A supply whose meniscus lies within g (S_a <= g / h) leaves nothing to cut.
    // h is the isothermal Moes film of the slice (see the parameter's note).
    const double S_a = in.outer_ring ? v.inlet_gap_ratio_outer : v.inlet_gap_ratio_inner;
    out.inlet_gap_ratio = S_a;
    const double F_flooded = (1.0 - phi) * out.rolling_thermal_factor *
                             tribology::biboulet_houpert_rolling_force_N(lub.eta0_Pas, uav, R, in.width_m, Q, E);
    double F = F_flooded * tribology::biboulet_houpert_starvation_factor(S_a);
    const double g = v.contact_film_limit_m;
    if (g > 0.0 && out.film_isothermal_m > 0.0) {
      const double S_g = g / out.film_isothermal_m;
      if (!(S_a > 0.0) || S_g < S_a) {
        double f_cut = tribology::rolling_force_beyond_film_N_m(lub.eta0_Pas, uav, R, g);
        if (S_a > 0.0) f_cut -= tribology::rolling_force_beyond_film_N_m(lub.eta0_Pas, uav, R, S_a * out.film_isothermal_m);
        F = std::max(0.0, F - f_cut * in.width_m);
        out.inlet_gap_ratio = S_g;
      }
    }
    out.rolling_starvation_factor = F_flooded > 0.0 ? F / F_flooded : 1.0;
    out.F_ehl_rolling_N = F;
  }
  out.M_solid_rolling_Nm = phi * tribology::solid_rolling_moment_Nm(v.c_r, v.e_r, Q);
  out.M_hysteresis_Nm = tribology::hysteresis_moment_Nm(Q, v.a_v, b);

  // Damping (Eq. 1-3): approach velocity positive when the bodies move together
  out.F_damping_N = -tribology::damping_force_N(in.normal_velocity_m_s, in.penetration_m,
                                                v.d_max_Ns_m, v.delta_max_m);
}

}  // namespace kegel

namespace kegel {

void evaluate_cell(const CellInput& in, const SurfacePair& sp, const ContactLubricantState& lub,
                   const FrictionParameters& fp, SliceResult& out) noexcept {
  out = SliceResult{};
  if (!(in.load_N > 0.0) || !(in.area_m2 > 0.0)) return;
  out.in_contact = true;
  const double E = sp.E_reduced_Pa();
  const double Q = in.load_N;
  out.area_m2 = in.area_m2;
  out.mean_pressure_Pa = Q / in.area_m2;
  out.max_pressure_Pa = out.mean_pressure_Pa;  // a cell carries one pressure
  const double urx = in.u1_x_m_s - in.u2_x_m_s, ury = in.u1_y_m_s - in.u2_y_m_s;
  const double us = std::sqrt(urx * urx + ury * ury);  // speeds: no overflow, and hypot is slow
  const double uex = in.u1_x_m_s + in.u2_x_m_s, uey = in.u1_y_m_s + in.u2_y_m_s;
  const double uav = 0.5 * std::sqrt(uex * uex + uey * uey);
  out.sliding_speed_m_s = us;
  out.entrainment_speed_m_s = uav;
  if (uav > 0.0) {  // Eq. 31-35 with the cell's velocity and the contact's load
    const double W_load = in.contact_load_N > 0.0 ? in.contact_load_N : Q;
    out.film_isothermal_m = tribology::elliptic_film_thickness_m(lub.eta0_Pas, uav, in.Rx_m, in.Ry_m, W_load,
                                                                 lub.alpha_p_1_Pa, E);
    out.thermal_factor = tribology::zhu_cheng_factor(out.max_pressure_Pa, E, us, 2.0 * uav, lub.deta_dtheta_Pas_K,
                                                     uav, lub.thermal_conductivity_W_mK);
    out.film_m = out.thermal_factor * out.film_isothermal_m;
  }
  out.Lambda = tribology::film_parameter(out.film_m, sp.sigma_m());
  out.phi = tribology::asperity_load_ratio(out.Lambda, sp.B(), sp.C());
  sliding_friction(urx, ury, us, Q, lub, fp, out);
}

}  // namespace kegel
