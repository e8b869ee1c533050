#include "kegel/core/lubricant.hpp"

#include <cmath>

#include "kegel/core/checks.hpp"

namespace kegel {
namespace {
constexpr double kZeroCelsius_K = 273.15;
constexpr double kPaPerBar = 1.0e5;
constexpr const char* kOwner = "LubricantParameters";
}  // namespace

Lubricant::Lubricant(const LubricantParameters& p) : p_(p) {
  using namespace detail;
  require_positive(kOwner, "vogel_K_Pas", p.vogel_K_Pas);
  require_positive(kOwner, "vogel_B_K", p.vogel_B_K);
  require_finite(kOwner, "vogel_C_degC", p.vogel_C_degC);
  require_positive(kOwner, "dicke_a1_bar", p.dicke_a1_bar);
  require_finite(kOwner, "dicke_a2_bar_per_K", p.dicke_a2_bar_per_K);
  require_finite(kOwner, "dicke_b1", p.dicke_b1);
  require_finite(kOwner, "dicke_b2_per_K", p.dicke_b2_per_K);
  require_positive(kOwner, "density_ref_kg_m3", p.density_ref_kg_m3);
  require_positive(kOwner, "density_ref_temperature_K", p.density_ref_temperature_K);
  require_finite(kOwner, "density_slope_kg_m3_K", p.density_slope_kg_m3_K);
  require_positive(kOwner, "thermal_conductivity_W_mK", p.thermal_conductivity_W_mK);
}

double Lubricant::vogel_pole_K() const noexcept { return kZeroCelsius_K - p_.vogel_C_degC; }

void check_temperature(const Lubricant& lub, double T) {
  const double pole = lub.vogel_pole_K();
  if (!std::isfinite(T) || T <= pole) {
    detail::fail("Lubricant", "temperature_K", T,
                 "a temperature above the Vogel pole " + std::to_string(pole) + " K");
  }
  if (!(density_kg_m3(lub, T) > 0.0)) {
    detail::fail("Lubricant", "temperature_K", T,
                 "a temperature at which the linear density law stays positive");
  }
}

void check_pressure(const Lubricant& lub, double T, double p_Pa) {
  check_temperature(lub, T);
  detail::require_nonnegative("Lubricant", "pressure_Pa", p_Pa);
  const auto& q = lub.parameters();
  const double theta = T - kZeroCelsius_K;
  const double p_bar = p_Pa / kPaPerBar;
  const double den = q.dicke_a1_bar + q.dicke_a2_bar_per_K * theta +
                     (q.dicke_b1 + q.dicke_b2_per_K * theta) * p_bar;
  if (!(den > 0.0)) {
    detail::fail("Lubricant", "pressure_Pa", p_Pa,
                 "a pressure at which the Dicke denominator a1 + a2*theta + (b1 + b2*theta)*p "
                 "stays positive (Eq. 7)");
  }
}

double viscosity_ambient_Pas(const Lubricant& lub, double T) noexcept {
  const auto& q = lub.parameters();
  const double theta = T - kZeroCelsius_K;  // Eq. 8 takes degC
  return q.vogel_K_Pas * std::exp(q.vogel_B_K / (theta + q.vogel_C_degC));
}

double viscosity_Pas(const Lubricant& lub, double T, double p_Pa) noexcept {
  const auto& q = lub.parameters();
  const double theta = T - kZeroCelsius_K;
  const double p_bar = p_Pa / kPaPerBar;  // Eq. 7 takes bar
  const double den = q.dicke_a1_bar + q.dicke_a2_bar_per_K * theta +
                     (q.dicke_b1 + q.dicke_b2_per_K * theta) * p_bar;
  return viscosity_ambient_Pas(lub, T) * std::exp(p_bar / den);
}

double pressure_viscosity_coefficient_per_Pa(const Lubricant& lub, double T) noexcept {
  const auto& q = lub.parameters();
  const double theta = T - kZeroCelsius_K;
  // d/dp [p / (a + b p)] at p = 0 is 1/a  (p in bar) -> convert 1/bar to 1/Pa.
  return 1.0 / ((q.dicke_a1_bar + q.dicke_a2_bar_per_K * theta) * kPaPerBar);
}

double density_kg_m3(const Lubricant& lub, double T) noexcept {
  const auto& q = lub.parameters();
  return q.density_ref_kg_m3 + q.density_slope_kg_m3_K * (T - q.density_ref_temperature_K);
}

double kinematic_viscosity_m2_s(const Lubricant& lub, double T) noexcept {
  return viscosity_ambient_Pas(lub, T) / density_kg_m3(lub, T);
}

}  // namespace kegel
