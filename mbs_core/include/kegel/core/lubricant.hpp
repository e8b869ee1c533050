// Lubricant model: parameters (a validated value type) and property functions.
//
// Sources (Wingertszahn et al., Lubricants 2023, 11, 369, "the seed paper"):
//   Eq. 8  Vogel:  eta0(theta) = K exp(B / (theta + C)),   theta in degC
//   Eq. 7  Dicke:  eta(p, theta) = eta0 exp(p / (a1 + a2 theta + (b1 + b2 theta) p)),  p in bar
//   Table A1: parameters of the reference oil FVA No. 3.
// Density: linear in temperature with the Table A1 "temperature density coefficient".
// Pressure-viscosity coefficient alpha_p0 = d ln(eta)/dp at p = 0 follows from Eq. 7:
//   alpha_p0 = 1 / (a1 + a2 theta)  [1/bar].
//
// Units: every function takes and returns SI (K, Pa, Pa s, kg/m^3, m^2/s, 1/Pa). The
// parameters keep the units of the published formulas, and their names say so.
// The property functions are noexcept and allocation-free (hot loop); call
// check_temperature() / check_pressure() at an input boundary first.
#pragma once

namespace kegel {

/// Published parameters of one lubricant (units in the names).
struct LubricantParameters {
  double vogel_K_Pas = 0.0;          ///< Vogel K (Table A1 gives mPa s; stored in Pa s)
  double vogel_B_K = 0.0;            ///< Vogel B (a temperature difference: K == degC)
  double vogel_C_degC = 0.0;         ///< Vogel C, added to theta in degC
  double dicke_a1_bar = 0.0;         ///< Dicke a1
  double dicke_a2_bar_per_K = 0.0;   ///< Dicke a2
  double dicke_b1 = 0.0;             ///< Dicke b1 (dimensionless)
  double dicke_b2_per_K = 0.0;       ///< Dicke b2
  double density_ref_kg_m3 = 0.0;    ///< density at density_ref_temperature_K
  double density_ref_temperature_K = 288.15;
  double density_slope_kg_m3_K = 0.0;  ///< d rho / d T (negative for oils)
  double thermal_conductivity_W_mK = 0.0;
};

/// A lubricant whose parameters have been checked (the constructor throws
/// std::invalid_argument naming the field, the value and what was expected).
class Lubricant {
 public:
  explicit Lubricant(const LubricantParameters& parameters);
  const LubricantParameters& parameters() const noexcept { return p_; }

  /// Lowest temperature the Vogel form is defined at (theta + C > 0), in K.
  double vogel_pole_K() const noexcept;

 private:
  LubricantParameters p_;
};

/// Throws std::invalid_argument unless temperature_K is finite, above the Vogel pole and
/// gives a positive density.
void check_temperature(const Lubricant& lub, double temperature_K);
/// Throws std::invalid_argument unless pressure_Pa is finite, >= 0 and the Dicke
/// denominator stays positive at this temperature.
void check_pressure(const Lubricant& lub, double temperature_K, double pressure_Pa);

/// Eq. 8: dynamic viscosity at ambient pressure [Pa s].
double viscosity_ambient_Pas(const Lubricant& lub, double temperature_K) noexcept;
/// Eq. 7 (Dicke): dynamic viscosity at pressure [Pa s].
double viscosity_Pas(const Lubricant& lub, double temperature_K, double pressure_Pa) noexcept;
/// Pressure-viscosity coefficient alpha_p0 = d ln(eta)/dp at p = 0 from Eq. 7 [1/Pa].
double pressure_viscosity_coefficient_per_Pa(const Lubricant& lub,
                                             double temperature_K) noexcept;
/// Density, linear in temperature [kg/m^3].
double density_kg_m3(const Lubricant& lub, double temperature_K) noexcept;
/// Kinematic viscosity at ambient pressure [m^2/s].
double kinematic_viscosity_m2_s(const Lubricant& lub, double temperature_K) noexcept;

}  // namespace kegel
