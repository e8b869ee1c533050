// Shared test data: FVA No. 3 (seed paper Table A1) in the units of LubricantParameters.
#pragma once

#include "kegel/core/lubricant.hpp"
#include "kegel/core/slice.hpp"

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

/// The friction parameters of kegel/data/friction/steel_mineral_oil.toml that the tests share
/// (limiting shear, Eq. 21-27 friction law, Eq. 19-20 rolling); each test adds its own.
inline kegel::FrictionParameters::Values friction_values() {
  kegel::FrictionParameters::Values v;
  v.gamma_L = 0.06;
  v.mu_s = 0.1;
  v.mu_d = 0.1;
  v.v_s_m_s = 1e-3;
  v.v_d_m_s = 2e-3;
  v.c_r = 5e-6;
  v.a_v = 0.007;
  return v;
}

}  // namespace kegel::test
