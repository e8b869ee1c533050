// Per-slice evaluation: hand calculations, limits, symmetry and the mechanism breakdown.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "kegel/core/slice.hpp"
#include "test_data.hpp"

namespace {
constexpr double kPi = 3.14159265358979323846;

kegel::FrictionParameters::Values params() {
  kegel::FrictionParameters::Values v = kegel::test::friction_values();  // tau_L0 0, e_r 1, delta_max 1 um
  v.d_max_Ns_m = 100.0;
  return v;
}

struct Fixture : ::testing::Test {
  kegel::Lubricant lub{kegel::test::fva3()};
  kegel::ContactLubricantState state = kegel::make_contact_lubricant_state(lub, 323.15);
  kegel::FrictionParameters fp{params()};
  kegel::SurfacePair sp{0.16e-6, 2.32, 0.97, 210e9 / 0.91};

  kegel::SliceInput slice(double Q, double u1, double u2) const {
    kegel::SliceInput in;
    in.load_N = Q;
    in.width_m = 0.7e-3;  // 30 slices over 20.7 mm
    in.reduced_radius_m = 7.5e-3;
    in.u1_x_m_s = u1;
    in.u2_x_m_s = u2;
    return in;
  }
  kegel::SliceResult eval(const kegel::SliceInput& in) const {
    kegel::SliceResult r;
    kegel::evaluate_slice(in, sp, state, fp, r);
    return r;
  }
};
}  // namespace

TEST_F(Fixture, UnloadedSliceIsOutOfContact) {
  const auto r = eval(slice(0.0, 5.0, 5.1));
  EXPECT_FALSE(r.in_contact);
  EXPECT_EQ(r.F_ehl_sliding_N[0], 0.0);
  EXPECT_EQ(r.M_hysteresis_Nm, 0.0);
  EXPECT_EQ(r.film_m, 0.0);
}

TEST_F(Fixture, HertzAndFilmByHand) {
  const double Q = 50.0, u = 5.0;
  const auto r = eval(slice(Q, u, u));
  const double E = 210e9 / 0.91, w = Q / 0.7e-3, R = 7.5e-3;
  const double b = std::sqrt(8 * w * R / (kPi * E));
  EXPECT_NEAR(r.half_width_m, b, 1e-15);
  EXPECT_NEAR(r.max_pressure_Pa, 2 * w / (kPi * b), 1e-6 * r.max_pressure_Pa);
  EXPECT_NEAR(r.mean_pressure_Pa, kPi / 4 * r.max_pressure_Pa, 1e-9 * r.max_pressure_Pa);
  const double h = kegel::tribology::moes_line_film_thickness_m(state.eta0_Pas, 2 * u, R, w, state.alpha_p_1_Pa, E);
  EXPECT_DOUBLE_EQ(r.film_isothermal_m, h);
  EXPECT_GT(r.thermal_factor, 0.0);
  EXPECT_LT(r.thermal_factor, 1.0);
  EXPECT_DOUBLE_EQ(r.film_m, r.thermal_factor * h);
  EXPECT_DOUBLE_EQ(r.Lambda, r.film_m / 0.16e-6);
  EXPECT_DOUBLE_EQ(r.phi, std::exp(-2.32 * std::pow(r.Lambda, 0.97)));
  // Johnson hysteresis with the slice half-width
  EXPECT_NEAR(r.M_hysteresis_Nm, Q * 0.007 * 2 * b / (3 * kPi), 1e-18);
}

TEST_F(Fixture, PureRollingHasNoSlidingFriction) {
  const auto r = eval(slice(50.0, 5.0, 5.0));
  EXPECT_EQ(r.sliding_speed_m_s, 0.0);
  EXPECT_EQ(r.F_ehl_sliding_N[0], 0.0);
  EXPECT_EQ(r.F_solid_sliding_N[0], 0.0);
  EXPECT_EQ(r.P_ehl_sliding_W + r.P_solid_sliding_W, 0.0);
  EXPECT_GT(r.F_ehl_rolling_N, 0.0);
  EXPECT_GT(r.M_hysteresis_Nm, 0.0);
}

TEST_F(Fixture, SlidingForcesOpposeSlipAndAreOdd) {
  const auto a = eval(slice(50.0, 5.05, 4.95));
  const auto b = eval(slice(50.0, 4.95, 5.05));
  EXPECT_LT(a.F_ehl_sliding_N[0], 0.0);  // roller faster than ring: friction brakes the roller
  EXPECT_DOUBLE_EQ(a.F_ehl_sliding_N[0], -b.F_ehl_sliding_N[0]);
  EXPECT_DOUBLE_EQ(a.F_solid_sliding_N[0], -b.F_solid_sliding_N[0]);
  // dissipated power equals -F . u_rel, and is positive
  const double urel = 0.1;
  EXPECT_NEAR(a.P_ehl_sliding_W, -a.F_ehl_sliding_N[0] * urel, 1e-12 * a.P_ehl_sliding_W);
  EXPECT_GT(a.P_ehl_sliding_W, 0.0);
}

TEST_F(Fixture, LateralSlipActsAlongTheContactLine) {
  auto in = slice(50.0, 5.0, 5.0);
  in.u1_y_m_s = 0.2;  // skew: the roller slides along its contact line
  const auto r = eval(in);
  EXPECT_NEAR(r.F_ehl_sliding_N[0], 0.0, 1e-15);
  EXPECT_LT(r.F_ehl_sliding_N[1], 0.0);
}

TEST_F(Fixture, TractionSaturatesAtLimitingShear) {
  const auto r = eval(slice(200.0, 6.0, 4.0));  // large slip: tau -> tau_L
  EXPECT_NEAR(r.tau_ehl_Pa, r.tau_L_Pa, 1e-6 * r.tau_L_Pa);
  EXPECT_NEAR(r.tau_L_Pa, 0.06 * r.mean_pressure_Pa, 1e-6 * r.tau_L_Pa);
  EXPECT_NEAR(-r.F_ehl_sliding_N[0], (1 - r.phi) * r.tau_L_Pa * r.area_m2, 1e-6 * r.tau_L_Pa * r.area_m2);
}

TEST_F(Fixture, NoEntrainmentMeansSolidContact) {
  const auto r = eval(slice(50.0, 0.05, -0.05));  // opposite surface speeds: u_av = 0
  EXPECT_EQ(r.film_m, 0.0);
  EXPECT_EQ(r.Lambda, 0.0);
  EXPECT_DOUBLE_EQ(r.phi, 1.0);
  EXPECT_EQ(r.F_ehl_rolling_N, 0.0);
  EXPECT_NEAR(-r.F_solid_sliding_N[0], 0.1 * 50.0, 1e-12);  // mu_d Q
  EXPECT_NEAR(r.M_solid_rolling_Nm, 5e-6 * 50.0, 1e-15);
}

TEST_F(Fixture, MixedWeightingMovesWithFilm) {
  // thicker film at higher speed: phi falls, the solid share falls
  const auto slow = eval(slice(50.0, 0.2, 0.19));
  const auto fast = eval(slice(50.0, 8.0, 7.99));
  EXPECT_GT(slow.phi, fast.phi);
  EXPECT_GT(fast.Lambda, slow.Lambda);
  EXPECT_GE(slow.phi, 0.0);
  EXPECT_LE(slow.phi, 1.0);
}

TEST_F(Fixture, DampingOpposesApproach) {
  auto in = slice(50.0, 5.0, 5.0);
  in.penetration_m = 2e-6;
  in.normal_velocity_m_s = 0.01;  // approaching
  EXPECT_NEAR(eval(in).F_damping_N, 100.0 * 0.01, 1e-12);
  in.penetration_m = 0.5e-6;
  EXPECT_NEAR(eval(in).F_damping_N, 50.0 * 0.01, 1e-12);
}

TEST(SliceParameters, ValidationNamesTheField) {
  auto v = params();
  v.v_d_m_s = 0.5e-3;
  try {
    kegel::FrictionParameters fp(v);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("v_d_m_s"), std::string::npos);
  }
  EXPECT_THROW(kegel::SurfacePair(0.0, 2.3, 0.97, 2e11), std::invalid_argument);
  const kegel::Lubricant lub{kegel::test::fva3()};
  EXPECT_THROW(kegel::make_contact_lubricant_state(lub, 100.0), std::invalid_argument);
}

TEST_F(Fixture, CompressionHeatingLowersContactViscosity) {
  const auto cold = eval(slice(80.0, 5.05, 5.0));
  EXPECT_DOUBLE_EQ(cold.contact_temperature_K, 323.15);  // Eq. 9 off by default
  auto v = params();
  v.gold_C1_Pa_K2 = 2.0e3;
  v.gold_C2_Pa_K = 7.0e6;
  const kegel::FrictionParameters hot_fp(v);
  kegel::SliceResult hot;
  kegel::evaluate_slice(slice(80.0, 5.05, 5.0), sp, state, hot_fp, hot);
  const double dT = hot.contact_temperature_K - 323.15;
  EXPECT_NEAR(2.0e3 * dT * dT + 7.0e6 * dT, hot.mean_pressure_Pa, 1e-6 * hot.mean_pressure_Pa);
  EXPECT_LT(hot.eta_contact_Pas, cold.eta_contact_Pas);
  v.gold_C2_Pa_K = 0.0;  // only one of the two set: rejected
  EXPECT_THROW(kegel::FrictionParameters{v}, std::invalid_argument);
}

TEST_F(Fixture, RibCellEllipticFilmAndSlidingOnly) {
  kegel::CellInput c;
  c.load_N = 2.0;
  c.area_m2 = 1e-8;  // 200 MPa in a 0.1 mm x 0.1 mm cell
  c.Rx_m = 0.2;
  c.Ry_m = 1.0;
  c.u1_x_m_s = 3.0;   // roller end
  c.u2_x_m_s = 2.5;   // rib
  const kegel::SurfacePair rib(0.24e-6, 1.90, 0.99, 210e9 / 0.91);
  kegel::SliceResult r;
  kegel::evaluate_cell(c, rib, state, fp, r);
  ASSERT_TRUE(r.in_contact);
  const double uav = 2.75;
  const double h = kegel::tribology::elliptic_film_thickness_m(state.eta0_Pas, uav, 0.2, 1.0, 2.0,
                                                               state.alpha_p_1_Pa, 210e9 / 0.91);
  EXPECT_DOUBLE_EQ(r.film_isothermal_m, h);
  EXPECT_DOUBLE_EQ(r.film_m, r.thermal_factor * h);
  EXPECT_DOUBLE_EQ(r.mean_pressure_Pa, 2e8);
  EXPECT_DOUBLE_EQ(r.phi, std::exp(-1.90 * std::pow(r.Lambda, 0.99)));
  EXPECT_LT(r.F_ehl_sliding_N[0], 0.0);  // the roller end is faster: friction brakes it
  EXPECT_EQ(r.F_ehl_rolling_N, 0.0);
  EXPECT_EQ(r.M_hysteresis_Nm, 0.0);
  EXPECT_NEAR(r.P_ehl_sliding_W + r.P_solid_sliding_W,
              -(r.F_ehl_sliding_N[0] + r.F_solid_sliding_N[0]) * 0.5, 1e-12);
}

// The EHL rolling force of a slice: (1 - phi) x thermal factor x starvation factor x
// Biboulet-Houpert, with the thermal model chosen in the parameters.
TEST_F(Fixture, RollingForceAppliesTheThermalAndStarvationFactors) {
  namespace tr = kegel::tribology;
  const double Q = 50.0, u = 5.0, E = 210e9 / 0.91, R = 7.5e-3, L = 0.7e-3;
  const double bh = tr::biboulet_houpert_rolling_force_N(state.eta0_Pas, u, R, L, Q, E);
  auto with = [&](kegel::RollingThermal t, double S) {
    auto v = params();
    v.rolling_thermal = t;
    v.inlet_gap_ratio_inner = S;
    kegel::SliceResult r;
    kegel::evaluate_slice(slice(Q, u, u), sp, state, kegel::FrictionParameters(v), r);
    return r;
  };
  const auto off = with(kegel::RollingThermal::Off, 0.0);
  EXPECT_NEAR(off.F_ehl_rolling_N, (1.0 - off.phi) * bh, 1e-12 * bh);
  const auto ai = with(kegel::RollingThermal::Aihara, 0.0);
  const double phiT = tr::aihara_thermal_factor(tr::thermal_loading_parameter(state.deta_dtheta_Pas_K, u,
                                                                               state.thermal_conductivity_W_mK));
  EXPECT_LT(phiT, 1.0);
  EXPECT_DOUBLE_EQ(ai.rolling_thermal_factor, phiT);
  EXPECT_NEAR(ai.F_ehl_rolling_N, (1.0 - ai.phi) * phiT * bh, 1e-12 * bh);
  const auto zc = with(kegel::RollingThermal::ZhuCheng, 0.0);
  EXPECT_DOUBLE_EQ(zc.rolling_thermal_factor, zc.thermal_factor);
  const auto st = with(kegel::RollingThermal::Off, 10.0);
  EXPECT_DOUBLE_EQ(st.rolling_starvation_factor, tr::biboulet_houpert_starvation_factor(10.0));
  EXPECT_NEAR(st.F_ehl_rolling_N, off.F_ehl_rolling_N * st.rolling_starvation_factor, 1e-12 * bh);
  EXPECT_DOUBLE_EQ(st.inlet_gap_ratio, 10.0);
  // a starvation ratio below Biboulet-Houpert's range is rejected
  auto bad = params();
  bad.inlet_gap_ratio_inner = 1.0;
  EXPECT_THROW(kegel::FrictionParameters{bad}, std::invalid_argument);
  bad = params();
  bad.inlet_gap_ratio_outer = -3.0;
  EXPECT_THROW(kegel::FrictionParameters{bad}, std::invalid_argument);
  bad = params();
  bad.contact_film_limit_m = -1e-4;
  EXPECT_THROW(kegel::FrictionParameters{bad}, std::invalid_argument);
}

// The supply is chosen by the slice's raceway (Eq. 44 at its S); the contact / hydraulic
// boundary g takes off the rolling force of the isoviscous-rigid film between g and the supply's
// meniscus (the flooded inlet X = -1 without a supply), by hand: 6 eta0 u I(g / R).
TEST_F(Fixture, InletSupplyByRingAndFilmLimit) {
  namespace tr = kegel::tribology;
  const double Q = 50.0, u = 5.0;
  auto run = [&](double S_in, double S_out, double g, bool outer) {
    auto v = params();
    v.rolling_thermal = kegel::RollingThermal::Off;
    v.inlet_gap_ratio_inner = S_in;
    v.inlet_gap_ratio_outer = S_out;
    v.contact_film_limit_m = g;
    auto in = slice(Q, u, u);
    in.outer_ring = outer;
    kegel::SliceResult r;
    kegel::evaluate_slice(in, sp, state, kegel::FrictionParameters(v), r);
    return r;
  };
  const auto flooded = run(0.0, 0.0, 0.0, false);
  EXPECT_EQ(flooded.inlet_gap_ratio, 0.0);
  EXPECT_EQ(flooded.rolling_starvation_factor, 1.0);
  // the ring selects its own ratio
  EXPECT_DOUBLE_EQ(run(10.0, 50.0, 0.0, false).inlet_gap_ratio, 10.0);
  EXPECT_DOUBLE_EQ(run(10.0, 50.0, 0.0, true).inlet_gap_ratio, 50.0);
  EXPECT_NEAR(run(10.0, 50.0, 0.0, true).F_ehl_rolling_N,
              flooded.F_ehl_rolling_N * tr::biboulet_houpert_starvation_factor(50.0), 1e-12);
  // the far field by hand: I(G) = sqrt(2/G - 1) + 2 asin(sqrt(G/2)) - 1 - pi/2
  const double R = 7.5e-3, w = 0.7e-3, eta0 = state.eta0_Pas;
  auto far = [&](double gap) {
    const double G = gap / R;
    if (G >= 1.0) return 0.0;
    return 6.0 * eta0 * u * (std::sqrt(2.0 / G - 1.0) + 2.0 * std::asin(std::sqrt(G / 2.0)) - 1.0 - M_PI / 2.0);
  };
  EXPECT_NEAR(tr::rolling_force_beyond_film_N_m(eta0, u, R, 0.4e-3), far(0.4e-3), 1e-12 * far(0.4e-3));
  EXPECT_EQ(tr::rolling_force_beyond_film_N_m(eta0, u, R, R), 0.0);  // beyond the flooded inlet
  // the film limit alone: the far field beyond g comes off the flooded force
  const double h = flooded.film_isothermal_m;
  const double g = 100.0 * h;
  const auto cut = run(0.0, 0.0, g, false);
  EXPECT_NEAR(cut.inlet_gap_ratio, 100.0, 1e-9);
  EXPECT_NEAR(cut.F_ehl_rolling_N, flooded.F_ehl_rolling_N - w * far(g), 1e-12);
  EXPECT_NEAR(cut.rolling_starvation_factor, cut.F_ehl_rolling_N / flooded.F_ehl_rolling_N, 1e-12);
  EXPECT_GT(cut.F_ehl_rolling_N, 0.0);
  // a supply within g (50 < 100) leaves nothing to cut: Eq. 44 at 50 alone
  const auto s50 = run(50.0, 0.0, g, false);
  EXPECT_DOUBLE_EQ(s50.inlet_gap_ratio, 50.0);
  EXPECT_NEAR(s50.F_ehl_rolling_N, flooded.F_ehl_rolling_N * tr::biboulet_houpert_starvation_factor(50.0), 1e-12);
  // a supply beyond g (500 > 100): Eq. 44 at 500, less the far field between g and 500 h
  const auto s500 = run(500.0, 0.0, g, false);
  EXPECT_NEAR(s500.inlet_gap_ratio, 100.0, 1e-9);
  EXPECT_NEAR(s500.F_ehl_rolling_N,
              flooded.F_ehl_rolling_N * tr::biboulet_houpert_starvation_factor(500.0) - w * (far(g) - far(500.0 * h)),
              1e-12);
  // a cut that would take more than the force leaves none (not a negative rolling force): a
  // lightly loaded slice (1 N, small force) cut at 1.2 times its film
  auto light = [&](double gap) {
    auto v = params();
    v.rolling_thermal = kegel::RollingThermal::Off;
    v.contact_film_limit_m = gap;
    kegel::SliceResult r;
    kegel::evaluate_slice(slice(1.0, u, u), sp, state, kegel::FrictionParameters(v), r);
    return r;
  };
  const auto light0 = light(0.0);
  ASSERT_GT(light0.F_ehl_rolling_N, 0.0);
  ASSERT_GT(w * far(1.2 * light0.film_isothermal_m), light0.F_ehl_rolling_N);
  EXPECT_EQ(light(1.2 * light0.film_isothermal_m).F_ehl_rolling_N, 0.0);
  // sliding friction and film do not change with the inlet of the rolling force
  EXPECT_DOUBLE_EQ(cut.film_m, flooded.film_m);
  EXPECT_DOUBLE_EQ(cut.F_ehl_sliding_N[0], flooded.F_ehl_sliding_N[0]);
}
