// Shared test data: FVA No. 3 (seed paper Table A1) in the units of LubricantParameters.
#pragma once

#include "kegel/core/lubricant.hpp"

namespace kegel::test {

inline kegel::LubricantParameters fva3() {
  kegel::LubricantParameters p;
  p.vogel_K_Pas = 0.062e-3;
  p.vogel_B_K = 1021.7;
  p.vogel_C_degC = 101.5517;
  p.dicke_a1_bar = 327.7918;
  p.dicke_a2_bar_per_K = 2.9862;
  p.dicke_b1 = 4.419e-3;
  p.dicke_b2_per_K = 3.0115e-4;
  p.density_ref_kg_m3 = 887.6;
  p.density_ref_temperature_K = 288.15;
  p.density_slope_kg_m3_K = -0.6;  // -6e-4 g/(ml K)
  p.thermal_conductivity_W_mK = 0.134;
  return p;
}

}  // namespace kegel::test
