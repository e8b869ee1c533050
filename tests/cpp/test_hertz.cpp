// Closed-form elliptic Hertz contact: sphere limit, inverse relation, and the rib contact of a
// 32216-like geometry against the cell model.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kegel/core/cell_contact.hpp"
#include "kegel/core/contact_geometry.hpp"
#include "kegel/core/hertz.hpp"

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kE = 210e9 / 0.91;
}  // namespace

TEST(Hertz, SphereOnFlatIsExact) {
  // known_values.md: a = (3 Q R / (2 E'))^(1/3), p0 = 3 Q / (2 pi a^2), delta = a^2 / R
  const double R = 0.01, Q = 100.0;
  const auto h = kegel::hertz_point_contact_load(R, R, kE, Q);  // sphere R on a flat: Rx = Ry = R
  const double a = std::cbrt(3 * Q * R / (2 * kE));
  EXPECT_NEAR(h.semi_major_m, a, 1e-9 * a);
  EXPECT_NEAR(h.semi_minor_m, a, 1e-9 * a);
  EXPECT_NEAR(h.approach_m, a * a / R, 1e-9 * a * a / R);
  EXPECT_NEAR(h.max_pressure_Pa, 3 * Q / (2 * kPi * a * a), 1e-9 * 3 * Q / (2 * kPi * a * a));
}

TEST(Hertz, ExactEllipticityAgainstEq32) {
  EXPECT_DOUBLE_EQ(kegel::hertz_ellipticity(1.0), 1.0);
  // Hamrock-Brewe (seed paper Eq. 32) is within a few per cent of the exact solution
  for (double ratio : {2.0, 10.0}) {
    const double k = kegel::hertz_ellipticity(ratio);
    EXPECT_NEAR(k, 1.0339 * std::pow(ratio, 0.636), 0.04 * k) << ratio;
  }
  EXPECT_NEAR(kegel::hertz_ellipticity(100.0), 1.0339 * std::pow(100.0, 0.636), 0.07 * 18.2);
}

TEST(Hertz, ApproachAndLoadAreInverse) {
  for (double ratio : {1.0, 3.0, 30.0}) {
    const auto h = kegel::hertz_point_contact_load(0.01, 0.01 * ratio, kE, 250.0);
    const auto g = kegel::hertz_point_contact_approach(0.01, 0.01 * ratio, kE, h.approach_m);
    EXPECT_NEAR(g.load_N, 250.0, 1e-9 * 250.0);
    EXPECT_GE(h.semi_major_m, h.semi_minor_m);
    EXPECT_NEAR(h.semi_major_m / h.semi_minor_m, h.ellipticity, 1e-12);
  }
  EXPECT_EQ(kegel::hertz_point_contact_approach(0.01, 0.02, kE, -1e-6).load_N, 0.0);
  // load grows as delta^(3/2)
  const double q1 = kegel::hertz_point_contact_approach(0.01, 0.05, kE, 1e-6).load_N;
  const double q2 = kegel::hertz_point_contact_approach(0.01, 0.05, kE, 4e-6).load_N;
  EXPECT_NEAR(q2 / q1, 8.0, 1e-9);
}

TEST(Hertz, EllipticRibContactAgreesWithCellModel) {
  // sphere (end of a roller, R_e = 0.22 m) against a cone face whose circumferential radius of
  // curvature is large: an elongated ellipse; the closed form must agree with the cell model
  const double Re = 0.22;
  kegel::RollerEnd end;
  end.sphere_radius_m = Re;
  end.cap_radius_m = 1.0;
  end.a_R = Eigen::Vector3d(0, 0, 1);
  // rib cone: psi = 100 deg (normal 10 deg off the axis), contact at r = 48 mm
  const double psi = 100.0 * kPi / 180.0, r_c = 0.048;
  kegel::RibFace rib{{0.0, psi}, 1.0};
  const Eigen::Vector3d n_out(std::cos(psi) * 0 + std::cos(psi), 0.0, -std::sin(psi));  // (e_r, e_z) at phi = 0
  const Eigen::Vector3d foot(r_c, 0.0, r_c / std::tan(psi));
  const double delta = 3e-6;  // interference
  end.p_RE = foot + (Re - delta) * Eigen::Vector3d(std::cos(psi), 0.0, -std::sin(psi));
  (void)n_out;
  // curvature radii from the gap on a fine stencil, then the closed form
  const int n = 64;
  const double w = 1.2e-3;  // window along the generator; 6x longer circumferentially
  std::vector<double> h(n * n);
  Eigen::Vector3d p, nrm;
  const double gmin = kegel::rib_gap(end, rib, n, n, w / n, 6 * w / n, h.data(), p, nrm);
  EXPECT_NEAR(-gmin, delta, 1e-9);
  std::vector<double> st(9);
  const double d = 1e-4;
  kegel::rib_gap(end, rib, 3, 3, d, d, st.data(), p, nrm);
  // relative radii of curvature from the gap: h(+d) + h(-d) - 2 h(0) = d^2 / R
  const double Rx = d * d / (st[0 * 3 + 1] + st[2 * 3 + 1] - 2 * st[4]);  // i: along the generator
  const double Ry = d * d / (st[1 * 3 + 0] + st[1 * 3 + 2] - 2 * st[4]);  // j: circumferential
  EXPECT_NEAR(Rx, Re, 1e-3 * Re);  // along the generator the rib is straight
  EXPECT_GT(Ry, 2 * Re);           // circumferentially the rib cone bends the same way
  const auto hz = kegel::hertz_point_contact_approach(Rx, Ry, kE, delta);
  kegel::CellContactModel model(n, n, w / n, 6 * w / n, kE);
  kegel::CellContactData data(model);
  ASSERT_EQ(kegel::solve_cell_contact(model, data, h.data(), hz.load_N), 0);
  // the cell model's approach for the Hertz load must equal the interference
  EXPECT_NEAR(data.approach_m, delta, 0.03 * delta);
}
