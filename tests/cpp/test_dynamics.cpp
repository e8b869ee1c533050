// Dynamic simulation: validated values, the coloured Jacobian against central differences,
// the no-throw boundary of the SUNDIALS callbacks, and a short run of a loaded 32216.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "kegel/core/dynamics.hpp"
#include "test_data.hpp"

long kegel_test_allocation_count();  // test_allocation.cpp counts operator new

namespace {
constexpr double kPi = 3.14159265358979323846;

// The 32216 as kegel.geometry derives it (kegel.quasi_static.bearing_model, 8 slices).
std::shared_ptr<kegel::BearingModel> bearing_32216() {
  kegel::BearingModelValues v;
  v.roller_count = 16;
  v.pitch_radius_m = 0.05425;
  v.roller_mid_z_m = 0.01599023111779526;
  v.roller_axis_angle_rad = 0.23633886041564023;
  v.apex_z_m = -0.20926326666789355;
  v.cup_angle_rad = 0.2730087030867106;
  v.cone_angle_rad = 0.19966901774456985;
  v.roller_mean_radius_m = 0.0085;
  v.roller_half_angle_rad = 0.036669842671070374;
  v.roller_length_m = 0.0227;
  v.roller_mass_kg = 0.04047906709329279;
  v.E_reduced_Pa = 230769230769.23074;
  v.rib_half_angle_rad = 1.7826752230016973;
  v.rib_apex_z_m = 0.039332887809233066;
  v.rib_outer_radius_m = 0.05517383807863252;
  v.end_sphere_radius_m = 0.21873977699160052;
  v.end_cap_radius_m = 0.007916389367501865;
  v.end_sphere_offset_m = -0.20738977699160052;
  v.profile = {0.017, 0.0227, 0.0005, 0.0207, 0.0, 0.002, 0.001};
  v.slices = 8;
  v.method = kegel::SliceMethod::Independent;
  return std::make_shared<kegel::BearingModel>(v);
}

kegel::DynamicValues values_32216() {
  kegel::DynamicValues d;
  d.roller_mass_kg = 0.04047906709329279;
  d.roller_inertia_axial_kgm2 = 1.4681518611203847e-06;
  d.roller_inertia_transverse_kgm2 = 2.467839508020331e-06;
  d.roller_com_offset_m = 0.0003703719185108552;
  d.cage_mass_kg = 0.05060930982832905;
  d.cage_inertia_axial_kgm2 = 0.00017356353862019592;
  d.cage_inertia_transverse_kgm2 = 9.125910119478777e-05;
  d.cage_pitch_radius_m = 0.05425;
  d.cage_pocket_clearance_m = 0.00034;
  d.cage_pocket_axial_clearance_m = 0.00034;
  d.cage_edge_height_m = 0.00357;
  d.ring_mass_kg = 0.4189093658098869;
  d.ring_inertia_axial_kgm2 = 4.3e-4;
  d.ring_inertia_transverse_kgm2 = 2.5e-4;
  d.damping_time_s = 2.5e-06;
  return d;
}

struct Fixture {
  kegel::Lubricant lub{kegel::test::fva3()};
  kegel::ContactLubricantState state = kegel::make_contact_lubricant_state(lub, 323.15);
  kegel::FrictionParameters fp{[] {
    kegel::FrictionParameters::Values v = kegel::test::friction_values();
    v.tau_L0_Pa = 2e6;
    return v;
  }()};
  kegel::SurfacePair race{0.16e-6, 2.32, 0.97, 2.3e11}, rib{0.24e-6, 1.9, 0.99, 2.3e11};
  std::shared_ptr<kegel::BearingModel> bearing = bearing_32216();
  std::shared_ptr<kegel::DynamicModel> model =
      std::make_shared<kegel::DynamicModel>(bearing, values_32216(), fp, race, rib, state);
  kegel::RingDrive drive;
  std::vector<double> y0;
  Fixture() {
    const double w = 2000.0 * kPi / 30.0;
    drive.time_s = {0.0};
    drive.speed_rad_s = {w};
    drive.axial_N = 6000.0;
    drive.radial_N = 3000.0;
    kegel::BearingData qs(*bearing);
    kegel::BearingLoads loads;
    loads.axial_N = 6000.0;
    loads.radial_N = 3000.0;
    EXPECT_EQ(kegel::solve_load_distribution(*bearing, qs, loads), 0);
    const double wc = 0.42 * w;
    y0 = kegel::initial_state(*model, qs, wc, std::vector<double>(16, -(w - wc) * 0.046 / 0.0085));
  }
};

class FailingElement final : public kegel::ForceElement {
 public:
  int wrench(int, const kegel::BodyKinematics&, const kegel::ForceContext& ctx, kegel::Wrench&) const noexcept override {
    return ctx.time_s > 1e-4 ? -1 : 0;
  }
  std::string message() const override { return "the CFD force table ended"; }
};
}  // namespace

TEST(Dynamics, ValuesAreValidated) {
  Fixture f;
  auto v = values_32216();
  v.roller_mass_kg = 0.0;
  EXPECT_THROW(kegel::DynamicModel(f.bearing, v, f.fp, f.race, f.rib, f.state), std::invalid_argument);
  v = values_32216();
  v.cage_points = 1;
  EXPECT_THROW(kegel::DynamicModel(f.bearing, v, f.fp, f.race, f.rib, f.state), std::invalid_argument);
  v = values_32216();
  v.cage_edge_height_m = 0.02;  // above the roller: the window could not hold it
  EXPECT_THROW(kegel::DynamicModel(f.bearing, v, f.fp, f.race, f.rib, f.state), std::invalid_argument);
  kegel::DragElementValues d;
  d.swirl_ratio = 5.0;
  EXPECT_THROW(kegel::DragElement{d}, std::invalid_argument);
  kegel::RingDrive bad = f.drive;
  bad.time_s = {0.0, 0.0};
  bad.speed_rad_s = {1.0, 2.0};
  EXPECT_THROW(kegel::DynamicSimulation(f.model, bad, {}, 0.0, f.y0), std::invalid_argument);
  EXPECT_THROW(kegel::DynamicSimulation(f.model, f.drive, {}, 0.0, std::vector<double>(3, 0.0)), std::invalid_argument);
}

TEST(Dynamics, ColouredJacobianMatchesCentralDifferences) {
  Fixture f;
  f.drive.tilt_free = true;  // every ring column in play
  const int N = f.model->state_size();
  kegel::DynamicData data(*f.model);
  std::vector<double> f0(N), J(size_t(N) * N), work(2 * size_t(N)), fp(N), fm(N);
  ASSERT_EQ(kegel::dynamic_rhs(*f.model, data, f.drive, 0.0, f.y0.data(), f0.data()), 0);
  ASSERT_EQ(kegel::dynamic_jacobian(*f.model, data, f.drive, 0.0, f.y0.data(), f0.data(), J.data(), work.data()), 0);
  // compare the columns of roller 0 (coloured) and of the cage and ring (one by one)
  std::vector<int> cols;
  for (int c = 0; c < 12; ++c) cols.push_back(c);
  for (int c = f.model->cage_offset(); c < N; ++c) cols.push_back(c);
  const double typ[4] = {1e-3, 1.0, 1.0, 10.0};
  for (int c : cols) {
    int local = c < f.model->cage_offset() ? (c % 12) / 3 : 0;
    if (c >= f.model->cage_offset() && c < f.model->ring_offset()) {
      const int k = c - f.model->cage_offset();
      local = k < 3 ? 0 : k < 7 ? 1 : k < 10 ? 2 : 3;
    } else if (c >= f.model->ring_offset()) {
      const int k = c - f.model->ring_offset();
      local = k < 3 ? 0 : k < 6 ? 2 : k < 8 ? 1 : 3;
    }
    const double h = 1e-7 * std::max(std::abs(f.y0[c]), typ[local]);
    std::vector<double> y = f.y0;
    y[c] += h;
    ASSERT_EQ(kegel::dynamic_rhs(*f.model, data, f.drive, 0.0, y.data(), fp.data()), 0);
    y[c] = f.y0[c] - h;
    ASSERT_EQ(kegel::dynamic_rhs(*f.model, data, f.drive, 0.0, y.data(), fm.data()), 0);
    double num = 0.0, den = 0.0;
    for (int r = 0; r < N; ++r) {
      const double ref = (fp[r] - fm[r]) / (2 * h);
      num += std::pow(J[size_t(c) * N + r] - ref, 2);
      den += ref * ref;
    }
    if (den > 0.0) EXPECT_LT(std::sqrt(num / den), 5e-3) << "column " << c;
  }
}

TEST(Dynamics, AFailingForceElementStopsTheRunWithoutAnException) {
  Fixture f;
  kegel::DynamicSimulation sim(f.model, f.drive, {}, 0.0, f.y0);
  sim.add_element(std::make_shared<FailingElement>());
  int flag = 0;
  EXPECT_NO_THROW(flag = sim.advance(1e-3));
  EXPECT_LT(flag, 0);
  EXPECT_NE(sim.message().find("the CFD force table ended"), std::string::npos) << sim.message();
  EXPECT_LT(sim.time(), 1e-3);
}

TEST(Dynamics, ALoadedBearingRunsAndBalancesItsPower) {
  Fixture f;
  kegel::DynamicSimulation sim(f.model, f.drive, {}, 0.0, f.y0);
  ASSERT_EQ(sim.advance(1e-3), 0) << sim.message();
  const auto q1 = sim.quadratures();
  ASSERT_EQ(sim.advance(3e-3), 0) << sim.message();
  const auto q2 = sim.quadratures();
  const double T = 2e-3;
  const double P_in = (q2[2] - q1[2]) / T;
  double P_contacts = 0.0;
  for (int i = 3; i < 18; ++i) P_contacts += (q2[i] - q1[i]) / T;
  P_contacts += (q2[18] - q1[18] + q2[19] - q1[19]) / T;  // damping, cage windows
  EXPECT_GT(P_in, 1.0);
  EXPECT_NEAR(P_contacts / P_in, 1.0, 0.02);
  const auto out = sim.outputs();
  EXPECT_GT(out.outer_ring_torque_Nm, 0.0);
  EXPECT_LT(out.max_penetration_m, 30e-6);
  double loaded = 0.0;
  for (const auto& r : out.rollers) loaded = std::max(loaded, r.inner_N);
  EXPECT_GT(loaded, 400.0);
}

TEST(Dynamics, TheRightHandSideDoesNotAllocate) {
  Fixture f;
  const int N = f.model->state_size();
  kegel::DynamicData data(*f.model);
  std::vector<double> ydot(N);
  ASSERT_EQ(kegel::dynamic_rhs(*f.model, data, f.drive, 0.0, f.y0.data(), ydot.data()), 0);  // warm
  const long before = kegel_test_allocation_count();
  for (int i = 0; i < 50; ++i) kegel::dynamic_rhs(*f.model, data, f.drive, 1e-6 * i, f.y0.data(), ydot.data());
  EXPECT_EQ(kegel_test_allocation_count() - before, 0);
}

// A contact temperature per ring (issue 27, item 6): the outer raceway's contacts take the outer
// ring's lubricant state, the inner raceway's and the rib's the inner ring's.

// The right-hand sides and outputs of the fixture's model (one state for all contacts) and of a
// model with the outer and inner rings' states given, at the fixture's state.
struct TwoModels {
  std::vector<double> a, b;
  kegel::DynamicOutputs o1, o2;
};

TwoModels rhs_with_ring_states(const Fixture& f, const kegel::ContactLubricantState& outer,
                               const kegel::ContactLubricantState& inner) {
  auto other = std::make_shared<kegel::DynamicModel>(f.bearing, values_32216(), f.fp, f.race, f.rib, outer, inner);
  const int N = f.model->state_size();
  kegel::DynamicData d1(*f.model), d2(*other);
  TwoModels r{std::vector<double>(N), std::vector<double>(N), {}, {}};
  EXPECT_EQ(kegel::dynamic_rhs(*f.model, d1, f.drive, 0.0, f.y0.data(), r.a.data(), &r.o1), 0);
  EXPECT_EQ(kegel::dynamic_rhs(*other, d2, f.drive, 0.0, f.y0.data(), r.b.data(), &r.o2), 0);
  return r;
}

TEST(RingTemperature, TwoEqualStatesGiveTheDynamicRightHandSideBitForBit) {
  Fixture f;
  const TwoModels r = rhs_with_ring_states(f, f.state, f.state);
  for (size_t i = 0; i < r.a.size(); ++i) EXPECT_EQ(r.a[i], r.b[i]) << "component " << i;
  EXPECT_EQ(r.o1.drive_torque_Nm, r.o2.drive_torque_Nm);
}

TEST(RingTemperature, AWarmerInnerRingThinsOnlyTheInnerRingsFilmsInTheDynamicModel) {
  Fixture f;
  // inner ring 10 K above the oil (50 degC), outer ring at the oil's temperature
  const kegel::ContactLubricantState warm = kegel::make_contact_lubricant_state(f.lub, 333.15);
  const TwoModels r = rhs_with_ring_states(f, f.state, warm);
  const kegel::DynamicOutputs &o1 = r.o1, &o2 = r.o2;
  using O = kegel::DynamicOutputs;
  // the same state: the outer raceway's contacts are unchanged, bit for bit
  for (int m = 0; m < 5; ++m) EXPECT_EQ(o1.power_W[O::kOuter][m], o2.power_W[O::kOuter][m]) << "mechanism " << m;
  EXPECT_EQ(o1.Lambda_min[O::kOuter], o2.Lambda_min[O::kOuter]);
  // the inner raceway's film is thinner (eta0 x 0.659 by Vogel, Eq. 8) and so its EHL rolling power
  EXPECT_LT(o2.Lambda_min[O::kInner], 0.95 * o1.Lambda_min[O::kInner]);
  EXPECT_LT(o2.power_W[O::kInner][kegel::BearingFriction::kEhlRolling],
            0.95 * o1.power_W[O::kInner][kegel::BearingFriction::kEhlRolling]);
}

TEST(RingTemperature, QuasiStaticFrictionTakesEachRingsState) {
  Fixture f;
  kegel::BearingData qs(*f.bearing);
  kegel::BearingLoads loads;
  loads.axial_N = 6000.0;
  ASSERT_EQ(kegel::solve_load_distribution(*f.bearing, qs, loads), 0);
  const double w = 2000.0 * kPi / 30.0;
  kegel::BearingFriction one, two, warm_inner;
  ASSERT_EQ(kegel::evaluate_bearing_friction(*f.bearing, qs, loads, w, f.state, f.fp, f.race, f.rib, one), 0);
  kegel::BearingData qs2(*f.bearing);
  ASSERT_EQ(kegel::solve_load_distribution(*f.bearing, qs2, loads), 0);
  ASSERT_EQ(kegel::evaluate_bearing_friction(*f.bearing, qs2, loads, w, f.state, f.state, f.fp, f.race, f.rib, two), 0);
  EXPECT_EQ(one.drive_torque_Nm, two.drive_torque_Nm);  // two equal states: bit-identical
  for (int c = 0; c < 3; ++c) EXPECT_EQ(one.Lambda_min[c], two.Lambda_min[c]);
  const kegel::ContactLubricantState warm = kegel::make_contact_lubricant_state(f.lub, 333.15);
  kegel::BearingData qs3(*f.bearing);
  ASSERT_EQ(kegel::solve_load_distribution(*f.bearing, qs3, loads), 0);
  ASSERT_EQ(kegel::evaluate_bearing_friction(*f.bearing, qs3, loads, w, f.state, warm, f.fp, f.race, f.rib, warm_inner),
            0);
  using B = kegel::BearingFriction;
  EXPECT_LT(warm_inner.Lambda_min[B::kInner], 0.95 * one.Lambda_min[B::kInner]);
  EXPECT_LT(warm_inner.Lambda_min[B::kRib], one.Lambda_min[B::kRib]);  // the rib is the inner ring's
  EXPECT_NEAR(warm_inner.Lambda_min[B::kOuter], one.Lambda_min[B::kOuter], 0.01 * one.Lambda_min[B::kOuter]);
  EXPECT_LT(warm_inner.power_W[B::kInner][B::kEhlRolling], 0.95 * one.power_W[B::kInner][B::kEhlRolling]);
  EXPECT_LT(warm_inner.drive_torque_Nm, one.drive_torque_Nm);
}
