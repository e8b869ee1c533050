#include "bindings.hpp"
#include "kegel/core/lubricant.hpp"

namespace nb = nanobind;
using namespace nb::literals;

namespace kegel::python {
namespace {

using TemperatureFunction = double (*)(const Lubricant&, double) noexcept;

/// Python entry point of a temperature-only property: check the temperature, then evaluate.
template <TemperatureFunction F>
double checked(const Lubricant& lub, double temperature_K) {
  check_temperature(lub, temperature_K);
  return F(lub, temperature_K);
}

}  // namespace

void bind_lubricant(nb::module_& m) {
  nb::class_<LubricantParameters>(m, "LubricantParameters",
                                  "Published lubricant parameters (units in the field names).")
      .def(nb::init<>())
      .def_rw("vogel_K_Pas", &LubricantParameters::vogel_K_Pas)
      .def_rw("vogel_B_K", &LubricantParameters::vogel_B_K)
      .def_rw("vogel_C_degC", &LubricantParameters::vogel_C_degC)
      .def_rw("dicke_a1_bar", &LubricantParameters::dicke_a1_bar)
      .def_rw("dicke_a2_bar_per_K", &LubricantParameters::dicke_a2_bar_per_K)
      .def_rw("dicke_b1", &LubricantParameters::dicke_b1)
      .def_rw("dicke_b2_per_K", &LubricantParameters::dicke_b2_per_K)
      .def_rw("density_ref_kg_m3", &LubricantParameters::density_ref_kg_m3)
      .def_rw("density_ref_temperature_K", &LubricantParameters::density_ref_temperature_K)
      .def_rw("density_slope_kg_m3_K", &LubricantParameters::density_slope_kg_m3_K)
      .def_rw("thermal_conductivity_W_mK", &LubricantParameters::thermal_conductivity_W_mK);

  nb::class_<Lubricant>(m, "Lubricant", "A lubricant with checked parameters.")
      .def(nb::init<const LubricantParameters&>(), "parameters"_a)
      .def_prop_ro("parameters", &Lubricant::parameters)
      .def_prop_ro("vogel_pole_K", &Lubricant::vogel_pole_K);

  // The Python entry points check their arguments (ValueError) before the noexcept kernels.
  m.def("viscosity_ambient_Pas", &checked<&viscosity_ambient_Pas>, "lubricant"_a, "temperature_K"_a,
        "Eq. 8 (Vogel): dynamic viscosity at ambient pressure.");
  m.def(
      "viscosity_Pas",
      [](const Lubricant& l, double T, double p) {
        check_pressure(l, T, p);
        return viscosity_Pas(l, T, p);
      },
      "lubricant"_a, "temperature_K"_a, "pressure_Pa"_a,
      "Eq. 7 (Dicke): dynamic viscosity at pressure.");
  m.def("pressure_viscosity_coefficient_per_Pa", &checked<&pressure_viscosity_coefficient_per_Pa>,
        "lubricant"_a, "temperature_K"_a, "alpha_p0 = d ln(eta)/dp at p = 0, from Eq. 7.");
  m.def("density_kg_m3", &checked<&density_kg_m3>, "lubricant"_a, "temperature_K"_a,
        "Density, linear in temperature.");
  m.def("kinematic_viscosity_m2_s", &checked<&kinematic_viscosity_m2_s>, "lubricant"_a,
        "temperature_K"_a, "Kinematic viscosity at ambient pressure.");
}

}  // namespace kegel::python
