// Python entry points of the friction laws (kegel._core.tribology). Each checks its arguments
// (ValueError naming the argument) before calling the noexcept kernel of tribology.hpp.
#include "bindings.hpp"
#include "kegel/core/checks.hpp"
#include "kegel/core/tribology.hpp"

namespace nb = nanobind;
using namespace nb::literals;

namespace kegel::python {
namespace {
constexpr const char* kOwner = "tribology";
void pos(const char* name, double v) { detail::require_positive(kOwner, name, v); }
void nonneg(const char* name, double v) { detail::require_nonnegative(kOwner, name, v); }
void finite(const char* name, double v) { detail::require_finite(kOwner, name, v); }
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
      [](double eta0, double u_av, double R, double L, double Q, double E) {
        pos("eta0_Pas", eta0); pos("u_av_m_s", u_av); pos("R_m", R); pos("L_m", L);
        pos("Q_N", Q); pos("E_reduced_Pa", E);
        return tribology::biboulet_houpert_rolling_force_N(eta0, u_av, R, L, Q, E);
      },
      "eta0_Pas"_a, "u_av_m_s"_a, "R_m"_a, "L_m"_a, "Q_N"_a, "E_reduced_Pa"_a,
      "Eq. 16-18: EHL rolling resistance force of a slice.");
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
}

}  // namespace kegel::python
