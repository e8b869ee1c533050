// Contact geometry for any pose: apex-matched nominal contact, approach, tilt, skew, rib gap on
// a cell grid, cage pocket forces.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kegel/core/contact_geometry.hpp"

namespace {
constexpr double kPi = 3.14159265358979323846;

// 32216 internal geometry with the apex at z = 0 (the same derivation as kegel/geometry.py).
struct Trb {
  double alpha_o, gamma, beta, alpha_i, r_M, z_M, Dw = 17e-3, L = 22.7e-3;
  Trb() {
    alpha_o = std::atan(0.42 / 1.5);
    const double k = Dw / 108.5e-3;
    gamma = 0.03;
    for (int i = 0; i < 200; ++i) gamma = std::atan(k * std::sin(alpha_o - gamma));
    beta = alpha_o - gamma;
    alpha_i = beta - gamma;
    r_M = 54.25e-3;
    z_M = r_M / std::tan(beta);
  }
  Eigen::Vector3d mid() const { return {r_M, 0.0, z_M}; }
  Eigen::Vector3d axis() const { return {std::sin(beta), 0.0, std::cos(beta)}; }
  kegel::RollerShape shape() const { return {0.5 * Dw, gamma, L}; }
};

kegel::RollerProfile flat_profile(double L) {
  kegel::RollerProfile::Values v;
  v.roller_diameter_m = 17e-3;
  v.length_m = L;
  return kegel::RollerProfile(v);
}

std::vector<double> positions(int n, double l) {
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = (i + 0.5) * l / n - 0.5 * l;
  return x;
}

Eigen::Vector3d rotate(const Eigen::Vector3d& v, const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()) * v;
}
}  // namespace

TEST(ContactGeometry, NominalApexMatchedPoseTouchesBothRaceways) {
  const Trb t;
  const auto prof = flat_profile(t.L);
  const auto xi = positions(20, 20e-3);
  std::vector<kegel::SliceGeometry> in(20), out(20);
  kegel::raceway_slice_geometry(t.shape(), prof, t.mid(), t.axis(), {0.0, t.alpha_i}, kegel::RacewaySide::Inner,
                                xi.data(), 20, in.data());
  kegel::raceway_slice_geometry(t.shape(), prof, t.mid(), t.axis(), {0.0, t.alpha_o}, kegel::RacewaySide::Outer,
                                xi.data(), 20, out.data());
  for (int i = 0; i < 20; ++i) {
    EXPECT_NEAR(in[i].interference_m, 0.0, 1e-12) << i;
    EXPECT_NEAR(out[i].interference_m, 0.0, 1e-12) << i;
    // normals point from the raceway to the roller, tangents are orthogonal to them
    EXPECT_NEAR(in[i].n_R.norm(), 1.0, 1e-14);
    EXPECT_GT((t.mid() - in[i].p_RC).dot(in[i].n_R), 0.0);
    EXPECT_GT((t.mid() - out[i].p_RC).dot(out[i].n_R), 0.0);
    EXPECT_NEAR(in[i].t_roll_R.dot(in[i].n_R), 0.0, 1e-14);
    EXPECT_NEAR(in[i].t_line_R.dot(in[i].n_R), 0.0, 1e-14);
  }
  // reduced radius at the middle: (rho / cos g)(r_i / cos a_i) / sum
  const double R1 = 8.5e-3 / std::cos(t.gamma), r_i = t.r_M - 8.5e-3 * std::cos(t.beta);
  const double R2 = r_i / std::cos(t.alpha_i);
  std::vector<kegel::SliceGeometry> mid(1);
  const double zero = 0.0;
  kegel::raceway_slice_geometry(t.shape(), prof, t.mid(), t.axis(), {0.0, t.alpha_i}, kegel::RacewaySide::Inner,
                                &zero, 1, mid.data());
  EXPECT_NEAR(mid[0].reduced_radius_m, R1 * R2 / (R1 + R2), 1e-12);
}

TEST(ContactGeometry, ApproachTiltAndSkew) {
  const Trb t;
  const auto prof = flat_profile(t.L);
  const int n = 21;
  const auto xi = positions(n, 20e-3);
  std::vector<kegel::SliceGeometry> g(n);
  const kegel::Cone cone{0.0, t.alpha_i};
  // move the roller towards the inner raceway along its normal by 10 um
  const Eigen::Vector3d n_i(-std::sin(t.alpha_i), 0.0, std::cos(t.alpha_i));  // e_z, e_r order: (x=r, z)
  const Eigen::Vector3d normal(std::cos(t.alpha_i), 0.0, -std::sin(t.alpha_i));
  (void)n_i;
  kegel::raceway_slice_geometry(t.shape(), prof, t.mid() - 10e-6 * normal, t.axis(), cone, kegel::RacewaySide::Inner,
                                xi.data(), n, g.data());
  for (const auto& s : g) EXPECT_NEAR(s.interference_m, 10e-6, 1e-9);
  // tilt in the axial plane by 1 mrad about the circumferential axis through M: linear in xi
  const Eigen::Vector3d e_theta(0.0, 1.0, 0.0);
  kegel::raceway_slice_geometry(t.shape(), prof, t.mid(), rotate(t.axis(), e_theta, 1e-3), cone,
                                kegel::RacewaySide::Inner, xi.data(), n, g.data());
  const double slope = (g[n - 1].interference_m - g[0].interference_m) / (xi[n - 1] - xi[0]);
  EXPECT_NEAR(std::abs(slope), 1e-3, 2e-5);
  // linear in xi about the middle slice (whose interference changes only by the second-order
  // change of the disc's extent, rho sin(gamma) dtheta)
  const double e0 = g[n / 2].interference_m;
  EXPECT_LT(std::abs(e0), 8.5e-3 * std::sin(t.gamma) * 1e-3 * 1.05);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(g[i].interference_m, e0 + slope * xi[i], 1e-9);
  // skew by 1 mrad about the contact normal: second order only
  kegel::raceway_slice_geometry(t.shape(), prof, t.mid(), rotate(t.axis(), normal, 1e-3), cone,
                                kegel::RacewaySide::Inner, xi.data(), n, g.data());
  for (const auto& s : g) EXPECT_LT(std::abs(s.interference_m), 1e-7);
}

TEST(ContactGeometry, RibGapOfASphereOverAPlane) {
  // psi = pi/2: the cone is the plane z = 0 with n_out = -e_z; sphere below it at gap g0
  const double R = 0.2, g0 = 2e-6;
  kegel::RollerEnd end;
  end.p_RE = Eigen::Vector3d(0.05, 0.0, -R - g0);
  end.a_R = Eigen::Vector3d::UnitZ();
  end.sphere_radius_m = R;
  end.cap_radius_m = 1.0;
  kegel::RibFace rib{{0.0, 0.5 * kPi}, 1.0};
  const int nx = 9, ny = 7;
  const double dx = 1e-4, dy = 2e-4;
  std::vector<double> h(nx * ny);
  Eigen::Vector3d p, nrm;
  const double gmin = kegel::rib_gap(end, rib, nx, ny, dx, dy, h.data(), p, nrm);
  EXPECT_NEAR(nrm.z(), -1.0, 1e-12);
  EXPECT_NEAR(p.x(), 0.05, 1e-12);
  double hmin = 1.0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const double x = (i + 0.5 - 0.5 * nx) * dx, y = (j + 0.5 - 0.5 * ny) * dy;
      const double exact = R - std::sqrt(R * R - x * x - y * y) + g0;
      EXPECT_NEAR(h[i * ny + j] + gmin, exact, 1e-13);
      hmin = std::min(hmin, exact);
    }
  EXPECT_NEAR(gmin, hmin, 1e-13);
  // a small cap leaves only the cells near the axis in contact range
  end.cap_radius_m = 1.5e-4;
  kegel::rib_gap(end, rib, nx, ny, dx, dy, h.data(), p, nrm);
  EXPECT_NEAR(h[0] + gmin, R, 1e-9);  // corner cell is off the cap
}

TEST(ContactGeometry, CagePocketForces) {
  const Trb t;
  const auto shape = t.shape();
  kegel::CagePocket pocket;
  pocket.half_width_m = 8.5e-3 + 0.17e-3;  // 0.34 mm total clearance
  pocket.taper_rad = t.gamma;
  const Eigen::Vector3d a = Eigen::Vector3d::UnitY(), zero = Eigen::Vector3d::Zero();
  // centred: no contact
  auto r = kegel::cage_pocket_contact(shape, pocket, zero, a, zero, zero, 8);
  EXPECT_EQ(r.normal_force_N, 0.0);
  // pushed 0.2 mm towards +x: the +x wall pushes back along -x, symmetric about the middle
  r = kegel::cage_pocket_contact(shape, pocket, Eigen::Vector3d(0.2e-3, 0, 0), a, zero, zero, 8);
  EXPECT_GT(r.normal_force_N, 0.0);
  EXPECT_NEAR(r.force_on_roller_P.x(), -r.normal_force_N * std::cos(t.gamma), 1e-9 * r.normal_force_N);
  // Palmgren for the whole length at the uniform penetration (0.2 - 0.17) mm cos(gamma)
  const double delta = 0.03e-3 * std::cos(t.gamma);
  const double palm = std::pow(delta * 1e3 * std::pow(t.L * 1e3, 0.8) / 3.84e-5, 1.0 / 0.9);
  EXPECT_NEAR(r.normal_force_N, palm, 1e-6 * palm);
  const auto l = kegel::cage_pocket_contact(shape, pocket, Eigen::Vector3d(-0.2e-3, 0, 0), a, zero, zero, 8);
  EXPECT_NEAR(l.force_on_roller_P.x(), -r.force_on_roller_P.x(), 1e-9 * r.normal_force_N);
  // sliding along the wall (roller moves radially, +z): friction mu N against the motion
  const auto f = kegel::cage_pocket_contact(shape, pocket, Eigen::Vector3d(0.2e-3, 0, 0), a,
                                            Eigen::Vector3d(0, 0, 0.5), zero, 8);
  EXPECT_NEAR(f.force_on_roller_P.z(), -0.1 * f.normal_force_N, 1e-9 * f.normal_force_N);
  // approaching the wall with damping increases the force
  pocket.d_max_Ns_m = 50.0;
  pocket.delta_max_m = 1e-6;
  const auto d = kegel::cage_pocket_contact(shape, pocket, Eigen::Vector3d(0.2e-3, 0, 0), a,
                                            Eigen::Vector3d(0.01, 0, 0), zero, 8);
  EXPECT_GT(d.normal_force_N, r.normal_force_N);
}

TEST(ContactGeometry, SliceInputProjectsVelocities) {
  kegel::SliceGeometry g;
  g.n_R = Eigen::Vector3d::UnitX();
  g.t_roll_R = Eigen::Vector3d::UnitY();
  g.t_line_R = Eigen::Vector3d::UnitZ();
  g.reduced_radius_m = 7e-3;
  g.interference_m = 2e-6;
  const auto in = kegel::make_slice_input(g, 1e5, 1e-3, Eigen::Vector3d(-0.1, 5.0, 0.2), Eigen::Vector3d(0, 4.9, 0));
  EXPECT_DOUBLE_EQ(in.load_N, 100.0);
  EXPECT_DOUBLE_EQ(in.u1_x_m_s, 5.0);
  EXPECT_DOUBLE_EQ(in.u1_y_m_s, 0.2);
  EXPECT_DOUBLE_EQ(in.u2_x_m_s, 4.9);
  EXPECT_DOUBLE_EQ(in.normal_velocity_m_s, 0.1);  // the roller moves towards the ring
  EXPECT_DOUBLE_EQ(in.reduced_radius_m, 7e-3);
}
