// Python entry points of the friction laws (kegel._core.tribology). Each checks its arguments
// (ValueError naming the argument) before calling the noexcept kernel of tribology.hpp.
#include "bindings.hpp"
#include "kegel/core/checks.hpp"
#include "kegel/core/slice.hpp"
#include "kegel/core/tribology.hpp"

#include <nanobind/stl/tuple.h>

namespace nb = nanobind;
using namespace nb::literals;

namespace kegel::python {
namespace {
constexpr const char* kOwner = "tribology";
void pos(const char* name, double v) { detail::require_positive(kOwner, name, v); }
void nonneg(const char* name, double v) { detail::require_nonnegative(kOwner, name, v); }
void finite(const char* name, double v) { detail::require_finite(kOwner, name, v); }

using V = FrictionParameters::Values;

void bind_slice(nb::module_& m) {
  nb::enum_<RollingThermal>(m, "RollingThermal", "Thermal reduction of the EHL rolling force.")
      .value("off", RollingThermal::Off)
      .value("aihara", RollingThermal::Aihara)
      .value("zhu_cheng", RollingThermal::ZhuCheng);
  nb::class_<V>(m, "FrictionParameterValues", "Friction-law parameters (see kegel/data/friction).")
      .def(nb::init<>())
      .def_rw("tau_L0_Pa", &V::tau_L0_Pa)
      .def_rw("gamma_L", &V::gamma_L)
      .def_rw("mu_s", &V::mu_s)
      .def_rw("mu_d", &V::mu_d)
      .def_rw("v_s_m_s", &V::v_s_m_s)
      .def_rw("v_d_m_s", &V::v_d_m_s)
      .def_rw("c_r", &V::c_r)
      .def_rw("e_r", &V::e_r)
      .def_rw("a_v", &V::a_v)
      .def_rw("d_max_Ns_m", &V::d_max_Ns_m)
      .def_rw("delta_max_m", &V::delta_max_m)
      .def_rw("gold_C1_Pa_K2", &V::gold_C1_Pa_K2)
      .def_rw("gold_C2_Pa_K", &V::gold_C2_Pa_K)
      .def_rw("rolling_thermal", &V::rolling_thermal)
      .def_rw("inlet_gap_ratio_inner", &V::inlet_gap_ratio_inner)
      .def_rw("inlet_gap_ratio_outer", &V::inlet_gap_ratio_outer)
      .def_rw("contact_film_limit_m", &V::contact_film_limit_m);
  nb::class_<FrictionParameters>(m, "FrictionParameters", "Checked friction-law parameters.")
      .def(nb::init<const V&>(), "values"_a)
      .def_prop_ro("values", &FrictionParameters::values)
      .def_prop_ro("compression_heating", &FrictionParameters::compression_heating);
  nb::class_<SurfacePair>(m, "SurfacePair", "Roughness and Zhou-Hoeprich constants of a contact.")
      .def(nb::init<double, double, double, double>(), "sigma_m"_a, "zhou_hoeprich_B"_a,
           "zhou_hoeprich_C"_a, "E_reduced_Pa"_a)
      .def_prop_ro("sigma_m", &SurfacePair::sigma_m)
      .def_prop_ro("E_reduced_Pa", &SurfacePair::E_reduced_Pa);
  nb::class_<ContactLubricantState>(m, "ContactLubricantState", "Lubricant at a bulk temperature.")
      .def_ro("temperature_K", &ContactLubricantState::temperature_K)
      .def_ro("eta0_Pas", &ContactLubricantState::eta0_Pas)
      .def_ro("alpha_p_1_Pa", &ContactLubricantState::alpha_p_1_Pa)
      .def_ro("deta_dtheta_Pas_K", &ContactLubricantState::deta_dtheta_Pas_K);
  m.def("make_contact_lubricant_state", &make_contact_lubricant_state, "lubricant"_a,
        "temperature_K"_a);
  nb::class_<SliceInput>(m, "SliceInput", "One slice's load, geometry and surface velocities.")
      .def(nb::init<>())
      .def_rw("load_N", &SliceInput::load_N)
      .def_rw("width_m", &SliceInput::width_m)
      .def_rw("reduced_radius_m", &SliceInput::reduced_radius_m)
      .def_rw("u1_x_m_s", &SliceInput::u1_x_m_s)
      .def_rw("u1_y_m_s", &SliceInput::u1_y_m_s)
      .def_rw("u2_x_m_s", &SliceInput::u2_x_m_s)
      .def_rw("u2_y_m_s", &SliceInput::u2_y_m_s)
      .def_rw("penetration_m", &SliceInput::penetration_m)
      .def_rw("normal_velocity_m_s", &SliceInput::normal_velocity_m_s)
      .def_rw("outer_ring", &SliceInput::outer_ring);
  using R = SliceResult;
  nb::class_<R>(m, "SliceResult", "Forces and moments of one slice by mechanism (on the roller).")
      .def_ro("in_contact", &R::in_contact)
      .def_ro("half_width_m", &R::half_width_m)
      .def_ro("max_pressure_Pa", &R::max_pressure_Pa)
      .def_ro("mean_pressure_Pa", &R::mean_pressure_Pa)
      .def_ro("area_m2", &R::area_m2)
      .def_ro("film_isothermal_m", &R::film_isothermal_m)
      .def_ro("thermal_factor", &R::thermal_factor)
      .def_ro("film_m", &R::film_m)
      .def_ro("Lambda", &R::Lambda)
      .def_ro("phi", &R::phi)
      .def_ro("contact_temperature_K", &R::contact_temperature_K)
      .def_ro("eta_contact_Pas", &R::eta_contact_Pas)
      .def_ro("tau_L_Pa", &R::tau_L_Pa)
      .def_ro("tau_ehl_Pa", &R::tau_ehl_Pa)
      .def_ro("mu_solid", &R::mu_solid)
      .def_ro("sliding_speed_m_s", &R::sliding_speed_m_s)
      .def_ro("entrainment_speed_m_s", &R::entrainment_speed_m_s)
      .def_prop_ro("F_ehl_sliding_N", [](const R& r) { return std::make_tuple(r.F_ehl_sliding_N[0], r.F_ehl_sliding_N[1]); })
      .def_prop_ro("F_solid_sliding_N", [](const R& r) { return std::make_tuple(r.F_solid_sliding_N[0], r.F_solid_sliding_N[1]); })
      .def_ro("F_ehl_rolling_N", &R::F_ehl_rolling_N)
      .def_ro("rolling_thermal_factor", &R::rolling_thermal_factor)
      .def_ro("rolling_starvation_factor", &R::rolling_starvation_factor)
      .def_ro("inlet_gap_ratio", &R::inlet_gap_ratio)
      .def_ro("M_solid_rolling_Nm", &R::M_solid_rolling_Nm)
      .def_ro("M_hysteresis_Nm", &R::M_hysteresis_Nm)
      .def_ro("F_damping_N", &R::F_damping_N)
      .def_ro("P_ehl_sliding_W", &R::P_ehl_sliding_W)
      .def_ro("P_solid_sliding_W", &R::P_solid_sliding_W);
  m.def(
      "evaluate_slice",
      [](const SliceInput& in, const SurfacePair& sp, const ContactLubricantState& lub,
         const FrictionParameters& fp) {
        nonneg("load_N", in.load_N); nonneg("width_m", in.width_m);
        pos("reduced_radius_m", in.reduced_radius_m);
        finite("u1_x_m_s", in.u1_x_m_s); finite("u1_y_m_s", in.u1_y_m_s);
        finite("u2_x_m_s", in.u2_x_m_s); finite("u2_y_m_s", in.u2_y_m_s);
        finite("penetration_m", in.penetration_m); finite("normal_velocity_m_s", in.normal_velocity_m_s);
        SliceResult out;
        evaluate_slice(in, sp, lub, fp, out);
        return out;
      },
      "slice"_a, "surfaces"_a, "lubricant_state"_a, "parameters"_a,
      "Evaluate one slice: film state and every friction force and moment by mechanism.");
}

}  // namespace

void bind_tribology(nb::module_& parent) {
  nb::module_ m = parent.def_submodule("tribology", "Friction laws of the seed paper (SI units).");

  m.def(
      "moes_line_film_thickness_m",
      [](double eta0, double u_sum, double R, double w, double alpha, double E) {
        pos("eta0_Pas", eta0); pos("u_sum_m_s", u_sum); pos("R_m", R); pos("w_N_m", w);
        pos("alpha_p_1_Pa", alpha); pos("E_reduced_Pa", E);
        return tribology::moes_line_film_thickness_m(eta0, u_sum, R, w, alpha, E);
      },
      "eta0_Pas"_a, "u_sum_m_s"_a, "R_m"_a, "w_N_m"_a, "alpha_p_1_Pa"_a, "E_reduced_Pa"_a,
      "Moes central film thickness of a line contact [m] (u_sum = u1 + u2).");
  m.def(
      "elliptic_film_thickness_m",
      [](double eta0, double u_av, double Rx, double Ry, double Q, double alpha, double E) {
        pos("eta0_Pas", eta0); pos("u_av_m_s", u_av); pos("Rx_m", Rx); pos("Ry_m", Ry);
        pos("Q_N", Q); pos("alpha_p_1_Pa", alpha); pos("E_reduced_Pa", E);
        return tribology::elliptic_film_thickness_m(eta0, u_av, Rx, Ry, Q, alpha, E);
      },
      "eta0_Pas"_a, "u_av_m_s"_a, "Rx_m"_a, "Ry_m"_a, "Q_N"_a, "alpha_p_1_Pa"_a, "E_reduced_Pa"_a,
      "Eq. 31-35: central film thickness of an elliptic contact [m].");
  m.def(
      "zhu_cheng_factor",
      [](double p0, double E, double u_rel, double u_sum, double deta, double u_av, double lam) {
        nonneg("p0_Pa", p0); pos("E_reduced_Pa", E); finite("u_rel_m_s", u_rel);
        nonneg("u_sum_m_s", u_sum); finite("deta_dtheta_Pas_K", deta); nonneg("u_av_m_s", u_av);
        pos("thermal_conductivity_W_mK", lam);
        return tribology::zhu_cheng_factor(p0, E, u_rel, u_sum, deta, u_av, lam);
      },
      "p0_Pa"_a, "E_reduced_Pa"_a, "u_rel_m_s"_a, "u_sum_m_s"_a, "deta_dtheta_Pas_K"_a,
      "u_av_m_s"_a, "thermal_conductivity_W_mK"_a, "Eq. 11-14: thermal film reduction factor.");
  m.def(
      "asperity_load_ratio",
      [](double Lambda, double B, double C) {
        nonneg("Lambda", Lambda); pos("B", B); pos("C", C);
        return tribology::asperity_load_ratio(Lambda, B, C);
      },
      "Lambda"_a, "B"_a, "C"_a, "Eq. 29: Zhou-Hoeprich asperity load ratio phi.");
  m.def(
      "bair_winer_shear_stress_Pa",
      [](double eta, double u_rel, double h, double tauL) {
        pos("eta_Pas", eta); finite("u_rel_m_s", u_rel); pos("h_m", h); pos("tau_L_Pa", tauL);
        return tribology::bair_winer_shear_stress_Pa(eta, u_rel, h, tauL);
      },
      "eta_Pas"_a, "u_rel_m_s"_a, "h_m"_a, "tau_L_Pa"_a,
      "Eq. 4-6, 10: limiting-shear lubricant shear stress (odd in u_rel).");
  m.def(
      "biboulet_houpert_rolling_force_N",
      [](double eta0, double u_m, double R, double L, double Q, double E) {
        pos("eta0_Pas", eta0); pos("u_mean_m_s", u_m); pos("R_m", R); pos("L_m", L);
        pos("Q_N", Q); pos("E_reduced_Pa", E);
        return tribology::biboulet_houpert_rolling_force_N(eta0, u_m, R, L, Q, E);
      },
      "eta0_Pas"_a, "u_mean_m_s"_a, "R_m"_a, "L_m"_a, "Q_N"_a, "E_reduced_Pa"_a,
      "EHL rolling resistance force of a line-contact slice (Biboulet-Houpert Part 1, Eq. 40-42; "
      "the seed's Eq. 16 is misprinted).");
  m.def(
      "biboulet_houpert_line_force",
      [](double U, double W) {
        pos("U", U); pos("W", W);
        return tribology::biboulet_houpert_line_force(U, W);
      },
      "U"_a, "W"_a,
      "Dimensionless rolling force F~ of Biboulet-Houpert Part 1 (U = 2 eta0 u_m/(E' R), W = w/(E' R)).");
  m.def(
      "aihara_thermal_factor",
      [](double L) { nonneg("L", L); return tribology::aihara_thermal_factor(L); }, "L"_a,
      "Aihara (1987) Eq. 21: phi_T = 1/(1 + 0.29 L^0.78), L the thermal loading parameter.");
  m.def(
      "thermal_loading_parameter",
      [](double deta, double u, double k) {
        finite("deta_dtheta_Pas_K", deta); nonneg("u_m_s", u); pos("thermal_conductivity_W_mK", k);
        return tribology::thermal_loading_parameter(deta, u, k);
      },
      "deta_dtheta_Pas_K"_a, "u_m_s"_a, "thermal_conductivity_W_mK"_a,
      "L = |d eta/d theta| u^2 / k (Murch-Wilson, Aihara).");
  m.def(
      "rolling_force_beyond_film_N_m",
      [](double eta0, double u_m, double R, double g) {
        pos("eta0_Pas", eta0); nonneg("u_mean_m_s", u_m); pos("R_m", R); pos("g_m", g);
        return tribology::rolling_force_beyond_film_N_m(eta0, u_m, R, g);
      },
      "eta0_Pas"_a, "u_mean_m_s"_a, "R_m"_a, "g_m"_a,
      "Rolling force per unit length [N/m] of the isoviscous-rigid film beyond the film height g "
      "(Reynolds, Biboulet-Houpert's rigid gap and flooded inlet X = -1): 6 eta0 u_m I(g/R), "
      "I(G) = sqrt(2/G - 1) + 2 asin(sqrt(G/2)) - 1 - pi/2, 0 for G >= 1; the contact / "
      "hydraulic boundary's cut.");
  m.def(
      "biboulet_houpert_starvation_factor",
      [](double S) { nonneg("S", S); return tribology::biboulet_houpert_starvation_factor(S); }, "S"_a,
      "Biboulet-Houpert Part 1 Eq. 44: starved over flooded rolling force, S >= 2 (0: flooded).");
  m.def(
      "cubic_friction_coefficient",
      [](double v, double mu_s, double mu_d, double v_s, double v_d) {
        finite("v_m_s", v); pos("mu_s", mu_s); pos("mu_d", mu_d); pos("v_s_m_s", v_s);
        if (!(v_d > v_s)) detail::fail(kOwner, "v_d_m_s", v_d, "a value > v_s_m_s");
        return tribology::cubic_friction_coefficient({mu_s, mu_d, v_s, v_d}, v);
      },
      "v_m_s"_a, "mu_s"_a, "mu_d"_a, "v_s_m_s"_a, "v_d_m_s"_a,
      "Eq. 21-27: regularised Coulomb coefficient mu(v), odd in v.");
  m.def(
      "damping_coefficient",
      [](double delta, double dmax, double dm) {
        finite("delta_m", delta); nonneg("d_max_Ns_m", dmax); pos("delta_max_m", dm);
        return tribology::damping_coefficient(delta, dmax, dm);
      },
      "delta_m"_a, "d_max_Ns_m"_a, "delta_max_m"_a, "Eq. 2-3: parametric damping coefficient.");

  bind_slice(m);
}

}  // namespace kegel::python
