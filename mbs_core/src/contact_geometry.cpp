#include "kegel/core/contact_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace kegel {
namespace {

struct Meridional {
  double r;            // distance from the z axis
  Eigen::Vector3d e_r; // unit radial direction (arbitrary on the axis)
};

inline Meridional meridional(const Eigen::Vector3d& p) noexcept {
  const double r = std::sqrt(p.x() * p.x() + p.y() * p.y());  // metres: no overflow; hypot is slow
  if (r > 0.0) return {r, Eigen::Vector3d(p.x() / r, p.y() / r, 0.0)};
  return {0.0, Eigen::Vector3d::UnitX()};
}

// Signed distance from the cone's generator line in the meridional plane of p (> 0 on the side
// of n_out), and n_out there.
inline double cone_distance(const Cone& c, const Eigen::Vector3d& p, Eigen::Vector3d& n_out) noexcept {
  const Meridional m = meridional(p);
  const double sp = std::sin(c.half_angle_rad), cp = std::cos(c.half_angle_rad);
  n_out = -sp * Eigen::Vector3d::UnitZ() + cp * m.e_r;
  return -sp * (p.z() - c.apex_z_m) + cp * m.r;
}

}  // namespace

void raceway_slice_geometry(const RollerShape& roller, const RollerProfile& profile,
                            const Eigen::Vector3d& p_RM, const Eigen::Vector3d& a_R_in,
                            const Cone& raceway, RacewaySide side, const double* xi_m, int n,
                            SliceGeometry* out) noexcept {
  const Eigen::Vector3d a_R = a_R_in.normalized();
  const double tan_g = std::tan(roller.half_angle_rad), cos_g = std::cos(roller.half_angle_rad);
  const double sgn = side == RacewaySide::Inner ? 1.0 : -1.0;
  const double ca = std::cos(raceway.half_angle_rad), sa = std::sin(raceway.half_angle_rad);
  for (int i = 0; i < n; ++i) {
    SliceGeometry& g = out[i];
    const double xi = xi_m[i];
    const Eigen::Vector3d c = p_RM + xi * a_R;  // disc centre
    Eigen::Vector3d n_out;
    const double s = cone_distance(raceway, c, n_out);
    const Eigen::Vector3d n = sgn * n_out;     // raceway -> roller
    const double dist = sgn * s;                // centre's distance from the raceway, roller side > 0
    const double rho = roller.mean_radius_m + xi * tan_g - profile.drop_m(xi);
    const double an = a_R.dot(n);
    const double ext = rho * std::sqrt(std::max(0.0, 1.0 - an * an));  // disc extent towards the cone
    g.xi_m = xi;
    g.interference_m = ext - dist;
    g.n_R = n;
    // the disc's point nearest the raceway, moved along the normal onto the raceway
    Eigen::Vector3d toward = n - an * a_R;  // in the disc plane, pointing away from the raceway
    const double tn = toward.norm();
    const Eigen::Vector3d x_disc = tn > 0.0 ? Eigen::Vector3d(c - rho * toward / tn) : Eigen::Vector3d(c - rho * n);
    g.p_RC = x_disc + g.interference_m * n;
    const Meridional m = meridional(g.p_RC);
    g.t_line_R = ca * Eigen::Vector3d::UnitZ() + sa * m.e_r;
    g.t_roll_R = Eigen::Vector3d(-m.e_r.y(), m.e_r.x(), 0.0);
    const double R1 = rho / cos_g;   // roller, normal curvature across its generator
    const double R2 = m.r / ca;      // raceway cone, normal curvature in the circumferential direction
    g.reduced_radius_m = side == RacewaySide::Inner ? R1 * R2 / (R1 + R2) : R1 * R2 / (R2 - R1);
  }
}

SliceInput make_slice_input(const SliceGeometry& g, double q, double width,
                            const Eigen::Vector3d& v1, const Eigen::Vector3d& v2) noexcept {
  SliceInput in;
  in.load_N = q * width;
  in.width_m = width;
  in.reduced_radius_m = g.reduced_radius_m;
  in.u1_x_m_s = v1.dot(g.t_roll_R);
  in.u1_y_m_s = v1.dot(g.t_line_R);
  in.u2_x_m_s = v2.dot(g.t_roll_R);
  in.u2_y_m_s = v2.dot(g.t_line_R);
  in.penetration_m = g.interference_m;
  in.normal_velocity_m_s = -(v1 - v2).dot(g.n_R);
  return in;
}

double rib_gap(const RollerEnd& end, const RibFace& rib, int nx, int ny, double dx, double dy,
               double* h0, Eigen::Vector3d& p_RC, Eigen::Vector3d& n_R, const unsigned char* cells) noexcept {
  Eigen::Vector3d n_out;
  const double s = cone_distance(rib.cone, end.p_RE, n_out);
  n_R = n_out;                                   // the roller lies on the n_out side of the rib
  p_RC = end.p_RE - s * n_out;                   // closest rib point (foot of the sphere centre)
  const Meridional m = meridional(p_RC);
  const Eigen::Vector3d t1 = std::cos(rib.cone.half_angle_rad) * Eigen::Vector3d::UnitZ() +
                             std::sin(rib.cone.half_angle_rad) * m.e_r;  // along the generator
  const Eigen::Vector3d t2(-m.e_r.y(), m.e_r.x(), 0.0);                  // circumferential
  const Eigen::Vector3d a = end.a_R.normalized();
  const double R = end.sphere_radius_m;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      if (cells && !cells[i * ny + j]) {
        h0[i * ny + j] = R;
        continue;
      }
      const Eigen::Vector3d q = p_RC + ((i + 0.5 - 0.5 * nx) * dx) * t1 + ((j + 0.5 - 0.5 * ny) * dy) * t2;
      // rib surface along the normal: Newton on the cone distance d(q + s n) = 0
      double sr = 0.0;
      for (int k = 0; k < 4; ++k) {
        Eigen::Vector3d nn;
        const double d = cone_distance(rib.cone, q + sr * n_R, nn);
        const double slope = nn.dot(n_R);
        if (!(std::abs(slope) > 1e-12)) break;
        sr -= d / slope;
      }
      const Eigen::Vector3d x_rib = q + sr * n_R;
      // sphere along the normal: the nearer root of |q + s n - c|^2 = R^2
      const Eigen::Vector3d w = q - end.p_RE;
      const double b = w.dot(n_R), disc = b * b - w.squaredNorm() + R * R;
      double gap = R;  // off the sphere, the cap or the rib: far away
      if (disc >= 0.0) {
        const double ss = -b - std::sqrt(disc);
        const Eigen::Vector3d x_sph = q + ss * n_R;
        const Eigen::Vector3d rel = x_sph - end.p_RE;
        const double off_axis = (rel - rel.dot(a) * a).norm();
        const bool on_cap = off_axis <= end.cap_radius_m;
        const bool on_rib = meridional(x_rib).r <= rib.outer_radius_m;
        if (on_cap && on_rib) gap = ss - sr;
      }
      h0[i * ny + j] = gap;
    }
  }
  // the true minimum is at the foot of the sphere centre (off the grid's cell centres)
  const double g_true = s - R;
  for (int k = 0; k < nx * ny; ++k) h0[k] -= g_true;
  return g_true;
}

CagePocketResult cage_pocket_contact(const RollerShape& roller, const CagePocket& pocket,
                                     const Eigen::Vector3d& p_PM, const Eigen::Vector3d& a_P_in,
                                     const Eigen::Vector3d& v_PM, const Eigen::Vector3d& w_P,
                                     int n_points) noexcept {
  CagePocketResult res;
  if (n_points < 2) return res;
  const Eigen::Vector3d a = a_P_in.normalized();
  const double tan_g = std::tan(roller.half_angle_rad);
  const double seg = roller.length_m / n_points;
  const double k = palmgren_stiffness(roller.length_m) / n_points;  // share of the line
  const double ct = std::cos(pocket.taper_rad), st = std::sin(pocket.taper_rad);
  for (int wall = -1; wall <= 1; wall += 2) {
    const Eigen::Vector3d e(wall * ct, -st, 0.0);  // outward normal of the wall
    Eigen::Vector3d dir = e - e.dot(a) * a;                        // disc support direction
    const double dn = dir.norm();
    if (!(dn > 0.0)) continue;
    dir /= dn;
    for (int kpt = 0; kpt < n_points; ++kpt) {
      const double xi = (kpt + 0.5) * seg - 0.5 * roller.length_m;
      const double rho = roller.mean_radius_m + xi * tan_g;
      const Eigen::Vector3d r = xi * a + rho * dir;  // contact point relative to the roller middle
      const Eigen::Vector3d p = p_PM + r;
      const double delta = p.dot(e) - pocket.half_width_m * ct;
      if (!(delta > 0.0)) continue;
      const Eigen::Vector3d v = v_PM + w_P.cross(r);
      const double v_n = v.dot(e);                     // approach velocity towards the wall
      double fn = k * std::pow(delta, 10.0 / 9.0) +
                  tribology::damping_coefficient(delta, pocket.d_max_Ns_m, pocket.delta_max_m) * v_n;
      fn = std::max(fn, 0.0);                          // the wall only pushes
      Eigen::Vector3d f = -fn * e;
      const Eigen::Vector3d vt = v - v_n * e;
      const double vs = vt.norm();
      if (vs > 0.0) f -= tribology::cage_friction_force_N(pocket.friction, fn, vs) * (vt / vs);
      res.force_on_roller_P += f;
      res.moment_on_roller_P += r.cross(f);
      res.normal_force_N += fn;
      res.max_penetration_m = std::max(res.max_penetration_m, delta);
    }
  }
  return res;
}

}  // namespace kegel
