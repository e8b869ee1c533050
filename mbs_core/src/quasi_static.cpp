#include "kegel/core/quasi_static.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kegel/core/checks.hpp"
#include "kegel/core/hertz.hpp"

namespace kegel {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kSpring_N_m = 1.0;       // stand-in for the cage on rollers out of contact
constexpr double kSpring_Nm_rad = 1e-3;

std::vector<double> nominal_reduced_radii(const BearingModelValues& v, const RollerProfile& prof,
                                          RacewaySide side) {
  const int n = v.slices;
  std::vector<double> xi(n), R(n);
  for (int i = 0; i < n; ++i) xi[i] = (i + 0.5) * v.roller_length_m / n - 0.5 * v.roller_length_m;
  const Eigen::Vector3d M(v.pitch_radius_m, 0.0, v.roller_mid_z_m);
  const Eigen::Vector3d a(std::sin(v.roller_axis_angle_rad), 0.0, std::cos(v.roller_axis_angle_rad));
  const Cone cone{v.apex_z_m, side == RacewaySide::Inner ? v.cone_angle_rad : v.cup_angle_rad};
  std::vector<SliceGeometry> g(n);
  raceway_slice_geometry({v.roller_mean_radius_m, v.roller_half_angle_rad, v.roller_length_m}, prof, M, a, cone,
                         side, xi.data(), n, g.data());
  for (int i = 0; i < n; ++i) R[i] = g[i].reduced_radius_m;
  return R;
}

const BearingModelValues& validated(const BearingModelValues& v) {
  using namespace detail;
  constexpr const char* o = "BearingModel";
  if (v.roller_count < 3 || v.roller_count > 200) fail(o, "roller_count", v.roller_count, "3..200");
  require_positive(o, "pitch_radius_m", v.pitch_radius_m);
  require_finite(o, "roller_mid_z_m", v.roller_mid_z_m);
  require_positive(o, "roller_axis_angle_rad", v.roller_axis_angle_rad);
  require_finite(o, "apex_z_m", v.apex_z_m);
  require_positive(o, "cup_angle_rad", v.cup_angle_rad);
  require_positive(o, "cone_angle_rad", v.cone_angle_rad);
  require_positive(o, "roller_mean_radius_m", v.roller_mean_radius_m);
  require_nonnegative(o, "roller_half_angle_rad", v.roller_half_angle_rad);
  require_positive(o, "roller_length_m", v.roller_length_m);
  require_nonnegative(o, "roller_mass_kg", v.roller_mass_kg);
  require_nonnegative(o, "cage_pocket_clearance_m", v.cage_pocket_clearance_m);
  require_positive(o, "E_reduced_Pa", v.E_reduced_Pa);
  require_finite(o, "rib_apex_z_m", v.rib_apex_z_m);
  require_range(o, "rib_half_angle_rad", v.rib_half_angle_rad, 0.5 * kPi, kPi);
  require_positive(o, "rib_outer_radius_m", v.rib_outer_radius_m);
  require_positive(o, "end_sphere_radius_m", v.end_sphere_radius_m);
  require_positive(o, "end_cap_radius_m", v.end_cap_radius_m);
  require_finite(o, "end_sphere_offset_m", v.end_sphere_offset_m);
  return v;
}

struct Pose {
  Eigen::Matrix3d R;
  Eigen::Vector3d d;
};

Pose ring_pose(const Eigen::Matrix<double, 5, 1>& x) {
  Pose p;
  p.R = (Eigen::AngleAxisd(x[3], Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(x[4], Eigen::Vector3d::UnitY()))
            .toRotationMatrix();
  p.d = x.head<3>();
  return p;
}

struct RollerEval {
  Eigen::Vector3d residual = Eigen::Vector3d::Zero();  // radial force, axial force, tilt moment
  Eigen::Vector3d F_ring = Eigen::Vector3d::Zero();    // force of the roller on the inner ring
  Eigen::Vector3d M_ring = Eigen::Vector3d::Zero();    // its moment about (0, 0, z_M)
  double Qo = 0.0, Qi = 0.0, Qrib = 0.0;
  bool ok = true;
};

RollerEval eval_roller(const BearingModel& m, BearingData& d, std::vector<SliceGeometry>& geo,
                       std::vector<double>& e, int j, const Pose& ring, const Eigen::Vector3d& dof,
                       double omega_c) {
  const auto& v = m.values();
  const RollerPose pose = m.roller_pose(j, dof[0], dof[1], dof[2]);
  const Eigen::Vector3d &er = pose.e_r, &et = pose.e_t, &M = pose.M, &a = pose.a;
  const Eigen::Vector3d ez = Eigen::Vector3d::UnitZ();
  const RollerShape shape{v.roller_mean_radius_m, v.roller_half_angle_rad, v.roller_length_m};
  const int n = v.slices;
  const double w = m.outer_line().width_m();
  RollerEval r;
  Eigen::Vector3d F = Eigen::Vector3d::Zero(), Mo = Eigen::Vector3d::Zero();
  const Eigen::Vector3d O(0.0, 0.0, v.roller_mid_z_m);
  double* xi = e.data() + n;     // second half of e holds the slice positions
  for (int i = 0; i < n; ++i) xi[i] = m.outer_line().position_m(i);

  // outer raceway (fixed ring)
  raceway_slice_geometry(shape, m.profile(), M, a, {v.apex_z_m, v.cup_angle_rad}, RacewaySide::Outer, xi, n,
                         geo.data());
  for (int i = 0; i < n; ++i) e[i] = geo[i].interference_m;
  if (solve_line_contact(m.outer_line(), d.outer_lines[j], e.data()) < 0) r.ok = false;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d f = d.outer_lines[j].line_load_N_m[i] * w * geo[i].n_R;
    F += f;
    Mo += (geo[i].p_RC - M).cross(f);
  }
  r.Qo = d.outer_lines[j].force_N;
  // inner raceway, in the inner ring's frame
  const Eigen::Vector3d Mi = ring.R.transpose() * (M - ring.d), ai = ring.R.transpose() * a;
  raceway_slice_geometry(shape, m.profile(), Mi, ai, {v.apex_z_m, v.cone_angle_rad}, RacewaySide::Inner, xi, n,
                         geo.data());
  for (int i = 0; i < n; ++i) e[i] = geo[i].interference_m;
  if (solve_line_contact(m.inner_line(), d.inner_lines[j], e.data()) < 0) r.ok = false;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d f = ring.R * (d.inner_lines[j].line_load_N_m[i] * w * geo[i].n_R);
    const Eigen::Vector3d p = ring.R * geo[i].p_RC + ring.d;
    F += f;
    Mo += (p - M).cross(f);
    r.F_ring -= f;
    r.M_ring -= (p - O).cross(f);
  }
  r.Qi = d.inner_lines[j].force_N;
  // rib (closed-form elliptic Hertz contact at the closest point)
  Eigen::Vector3d pc, nc;
  const double gmin = m.rib_closest(Mi, ai, pc, nc);
  if (gmin < 0.0) {
    r.Qrib = m.rib_hertz(-gmin).load_N;
    const Eigen::Vector3d f = ring.R * (r.Qrib * nc);
    const Eigen::Vector3d p = ring.R * pc + ring.d;
    F += f;
    Mo += (p - M).cross(f);
    r.F_ring -= f;
    r.M_ring -= (p - O).cross(f);
  }
  // centrifugal force and the stand-in cage spring
  F += v.roller_mass_kg * omega_c * omega_c * (v.pitch_radius_m + dof[0]) * er;
  F -= kSpring_N_m * (dof[0] * er + dof[1] * ez);
  Mo -= kSpring_Nm_rad * dof[2] * et;
  r.residual = Eigen::Vector3d(F.dot(er), F.dot(ez), Mo.dot(et));
  return r;
}

// One roller's 3 DOF for a fixed ring pose: chord Newton, with a trust-region
// (Levenberg-Marquardt) step when the Newton step is too long or does not reduce the residual.
//
// An unloaded roller touches the cup only (centrifugal force): the cup's normal force has a
// component along the cup generator that pushes the roller towards the large end, and nothing
// but the weak stand-in spring resists a slide along the cup until the roller meets the rib. The
// Jacobian is then singular in that direction: the Newton step is huge, and scaling the whole
// step down to the step limit also scaled away the correction of the well-conditioned normal
// direction, so the roller stalled where the iteration happened to leave it (Table 3 at 15 kN:
// unloaded rollers with 17 N or 182 N of cup load and up to 160 N of unbalanced force, by the
// sweep's history; the friction torque moved by 5 %). The trust-region step corrects the normal
// direction fully and walks along the cup by at most the trust radius per step, accepting steps
// that do not increase the residual (the slide is a plateau of the residual) until the rib
// takes the roller.
RollerEval solve_roller(const BearingModel& m, BearingData& d, std::vector<SliceGeometry>& geo, std::vector<double>& e,
                        int j, const Pose& ring, double omega_c, double scale) {
  const double L = m.values().roller_length_m;
  Eigen::Vector3d x(d.rollers[j].u_m, d.rollers[j].w_m, d.rollers[j].tilt_rad);
  const Eigen::Vector3d h(1e-9, 1e-9, 1e-9 / L);
  const Eigen::Vector3d limit(5e-6, 5e-6, 5e-6 / L);
  const Eigen::Vector3d D(1.0, 1.0, L);  // scaled unknowns D x: metres
  RollerEval r = eval_roller(m, d, geo, e, j, ring, x, omega_c);
  RollerState& st = d.rollers[j];
  auto norm = [&](const Eigen::Vector3d& q) { return std::hypot(std::hypot(q[0], q[1]), q[2] / L); };
  auto res_max = [&](const Eigen::Vector3d& q) {
    return std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2]) / L});
  };
  bool fresh = false;         // the Jacobian was computed at this iterate
  int walks = 0;              // slides along the cup (below) of a roller free of the inner ring
  double radius = 5e-6;       // trust radius of the Levenberg-Marquardt step (scaled, m)
  constexpr double kRadiusMax = 2e-4, kRadiusMin = 1e-13;
  for (int it = 0; it < 300; ++it) {
    if (res_max(r.residual) <= 1e-11 * scale) break;
    if (!st.has_jacobian) {
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector3d xp = x;
        xp[k] += h[k];
        st.jacobian.col(k) = (eval_roller(m, d, geo, e, j, ring, xp, omega_c).residual - r.residual) / h[k];
      }
      st.has_jacobian = true;
      fresh = true;
    }
    const double n0 = norm(r.residual);
    const Eigen::Vector3d dx = st.jacobian.fullPivLu().solve(-r.residual);
    const bool short_step = dx.allFinite() && (dx.cwiseAbs().array() <= limit.array()).all();
    if (short_step) {
      RollerEval rn = eval_roller(m, d, geo, e, j, ring, x + dx, omega_c);
      const double n1 = norm(rn.residual);
      if (n1 <= 0.5 * n0 || (fresh && n1 < n0)) {
        // Broyden's update: the Jacobian takes the secant of the step, so that the chord steps
        // converge superlinearly (a Jacobian from an earlier state contracted the residual by
        // only 0.3-0.5 per step: 15-20 evaluations per roller after a 1e-9 m move of the ring)
        const Eigen::Vector3d y = rn.residual - r.residual;
        const double ss = dx.squaredNorm();
        if (ss > 0.0 && y.allFinite()) st.jacobian += (y - st.jacobian * dx) * dx.transpose() / ss;
        x += dx;
        r = rn;
        fresh = false;
        continue;
      }
    }
    if (!fresh) {
      // the reused Jacobian no longer serves: take a fresh one at this iterate
      st.has_jacobian = false;
      continue;
    }
    // trust-region step with the fresh Jacobian, in the scaled unknowns y = D x and the scaled
    // residual (force, force, moment / L)
    Eigen::Matrix3d Js = st.jacobian;
    for (int k = 0; k < 3; ++k) Js.col(k) /= D[k];
    Js.row(2) /= L;
    Eigen::Vector3d rs = r.residual;
    rs[2] /= L;
    const Eigen::Matrix3d A = Js.transpose() * Js;
    const Eigen::Vector3d g = Js.transpose() * rs;
    const double a_scale = A.diagonal().maxCoeff();
    if (!(a_scale > 0.0) || !std::isfinite(a_scale)) break;
    auto lm_step = [&](double lambda) {
      return Eigen::Vector3d((A + lambda * a_scale * Eigen::Matrix3d::Identity()).ldlt().solve(-g));
    };
    bool accepted = false;
    while (!accepted && radius >= kRadiusMin) {
      // the smallest damping (by bisection in log space) whose step fits the trust radius
      double lo = 1e-14, hi = 1e4;
      Eigen::Vector3d dy = lm_step(lo);
      if (!(dy.allFinite() && dy.norm() <= radius)) {
        for (int b = 0; b < 60; ++b) {
          const double mid = std::sqrt(lo * hi);
          dy = lm_step(mid);
          if (dy.allFinite() && dy.norm() <= radius) hi = mid; else lo = mid;
        }
        dy = lm_step(hi);
      }
      const Eigen::Vector3d step = dy.cwiseQuotient(D);
      RollerEval rn = eval_roller(m, d, geo, e, j, ring, x + step, omega_c);
      // a step on the plateau (the residual not larger) is taken only downhill, along the net
      // force: moving against it (e.g. away from the rib along the cup) raises the energy
      const double n1 = norm(rn.residual);
      if (rn.ok && (n1 < n0 * (1.0 - 1e-12) || (n1 <= n0 * (1.0 + 1e-12) && dy.dot(rs) >= 0.0))) {
        x += step;
        r = rn;
        accepted = true;
        radius = std::min(2.0 * radius, kRadiusMax);
      } else {
        radius *= 0.25;
      }
    }
    if (!accepted) {
      // No step of the linearised least-squares problem reduces the residual: the roller sits
      // on a plateau (the slide along the cup, where the Jacobian has no stiffness). Follow the
      // net force (the steepest descent of the potential energy of contacts and centrifugal
      // force) while it keeps pointing the same way, doubling the step after each accepted one
      // and shortening it when the force reverses (the roller has met the rib).
      // A roller that touches neither the cone nor the rib (its ring has moved away) and has
      // slid kMaxWalks times in this call without meeting the rib is held where it is by its
      // cage pocket
      // (the pocket's faces bound its travel along the cup in a real bearing); the residual
      // along the cup generator is then the pocket's force (see the residual below). Walking on
      // cost up to 300 iterations a roller per ring iteration (32216, Fr = 20 kN: 80 s a
      // point; 40 s with the limit) and still stalled short of the rib; a limit over the whole
      // load distribution instead of per call left the ring iteration without convergence.
      constexpr int kMaxWalks = 3;
      if (r.Qi == 0.0 && r.Qrib == 0.0 && ++walks > kMaxWalks) break;
      const Eigen::Vector3d dir = rs / rs.norm();
      double len = 5e-6;
      bool moved = false;
      for (int k = 0; k < 80 && len >= kRadiusMin; ++k) {
        const Eigen::Vector3d step = (len * dir).cwiseQuotient(D);
        RollerEval rn = eval_roller(m, d, geo, e, j, ring, x + step, omega_c);
        Eigen::Vector3d rsn = rn.residual;
        rsn[2] /= L;
        if (rn.ok && rsn.allFinite() && rsn.dot(dir) >= 0.0) {
          x += step;
          r = rn;
          moved = true;
          len = std::min(2.0 * len, kRadiusMax);
          if (rsn.dot(dir) < 0.5 * rs.dot(dir)) break;  // the force falls: another contact takes over
        } else {
          len *= 0.25;
        }
      }
      if (!moved) break;
      radius = 5e-6;
    }
    st.has_jacobian = false;  // a fresh Jacobian at the new iterate
    fresh = false;
  }
  d.rollers[j].u_m = x[0];
  d.rollers[j].w_m = x[1];
  d.rollers[j].tilt_rad = x[2];
  d.rollers[j].outer_N = r.Qo;
  d.rollers[j].inner_N = r.Qi;
  d.rollers[j].rib_N = r.Qrib;
  Eigen::Vector3d res = r.residual;
  if (r.Qi == 0.0 && r.Qrib == 0.0) {
    // free of the inner ring (whichever way its iteration ended: the walk limit, no step along
    // the net force, or the iteration limit on the slide's plateau, which is how the 32216 at
    // Fr = 20 kN ends): the component along the cup generator (in the roller's plane,
    // radial and axial) is carried by the cage pocket, which holds the roller's place along
    // the cup; only the balance across the cup and of the tilt moment is the roller's own
    const double ao = m.values().cup_angle_rad;
    const Eigen::Vector2d t(std::sin(ao), std::cos(ao));
    const Eigen::Vector2d f = res.head<2>();
    res.head<2>() = f - f.dot(t) * t;
  }
  d.rollers[j].residual = std::max({std::abs(res[0]), std::abs(res[1]), std::abs(res[2]) / L}) / scale;
  return r;
}

// The ring's start under a combined load or an imposed tilt: the rigid-ring load distribution
// with a power-law contact per roller (its two contacts in series, Q = K (delta / 2 - drop)^n;
// Palmgren's line contact has n = 10/9). Roller j sits at psi_j = 2 pi j / Z, at the pitch point
// p_j = (r_p cos psi_j, r_p sin psi_j, z_M); its approach is delta_j = e_j . (R p_j + t - p_j)
// along e_j = (cos(alpha) cos(psi_j), cos(alpha) sin(psi_j), -sin(alpha)) for the ring's tilt R
// and translation t. The balance sum_j Q_j e_j = (Fr, 0, -Fa) is solved for t by a damped
// Newton. Cold, from Palmgren's axial start alone, the combined-load point (32216, Fa 6 kN,
// Fr 6.5 kN) took 7 ring iterations and 1313 roller evaluations (the ring's steps are limited to
// 10 um); with this start and the refit of K and n in solve_load_distribution, 3 iterations
// and 729 evaluations. At 10 mrad the solution lies 0.31 mm from the untilted start.
struct RigidRing {
  int Z = 0;
  double sa = 0.0, ca = 1.0, r_p = 0.0, z_M = 0.0, drop = 0.0;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();

  // half the approach of roller j less the profile drop (the approach of each of its contacts)
  double contact_approach(int j, const Eigen::Vector3d& t, Eigen::Vector3d& e) const noexcept {
    const double psi = 2.0 * kPi * j / Z, c = std::cos(psi), s = std::sin(psi);
    e = Eigen::Vector3d(ca * c, ca * s, -sa);
    const Eigen::Vector3d p(r_p * c, r_p * s, z_M);
    return 0.5 * e.dot(R * p + t - p) - drop;
  }
};

// Solves the balance for t (t on entry: the start); true, with t, when it is met within 1e-3 of
// the load (t is left as it was otherwise).
bool rigid_ring_start(const RigidRing& g, double K, double n, double Fa, double Fr, Eigen::Vector3d& t) noexcept {
  const Eigen::Vector3d target(Fr, 0.0, -Fa);
  auto balance = [&](const Eigen::Vector3d& tt, Eigen::Vector3d& f, Eigen::Matrix3d& J) {
    f = -target;
    J.setZero();
    Eigen::Vector3d e;
    for (int j = 0; j < g.Z; ++j) {
      const double dc = g.contact_approach(j, tt, e);
      if (!(dc > 0.0)) continue;
      const double q = K * std::pow(dc, n), dq = n * q / dc;  // dQ / d(contact approach)
      f += q * e;
      J += (0.5 * dq) * e * e.transpose();
    }
  };
  const double load = Fa + Fr;
  Eigen::Vector3d x = t, f, fn;
  Eigen::Matrix3d J, Jn;
  balance(x, f, J);
  for (int it = 0; it < 100 && f.cwiseAbs().maxCoeff() > 1e-9 * load; ++it) {
    const Eigen::Vector3d dx = J.fullPivLu().solve(-f);
    if (!dx.allFinite()) break;
    double step = 1.0;
    for (int k = 0; k < 40; ++k, step *= 0.5) {
      balance(x + step * dx, fn, Jn);
      if (fn.norm() < f.norm()) break;
    }
    if (!(fn.norm() < f.norm())) break;
    x += step * dx;
    f = fn;
    J = Jn;
  }
  if (!(f.cwiseAbs().maxCoeff() <= 1e-3 * load)) return false;
  t = x;
  return true;
}

Eigen::Matrix<double, 5, 1> ring_residual(const BearingModel& m, BearingData& d, std::vector<SliceGeometry>& geo,
                                          std::vector<double>& e, const Eigen::Matrix<double, 5, 1>& x,
                                          const BearingLoads& L, double scale, bool chain = false) {
  const Pose ring = ring_pose(x);
  Eigen::Vector3d F(L.radial_N, 0.0, L.axial_offset_controlled ? 0.0 : -L.axial_N), M(0.0, L.tilt_moment_Nm, 0.0);
  const int Z = m.values().roller_count;
  if (d.symmetric) {
    // every roller as roller 0, rotated: the radial forces and the moments cancel
    const RollerEval r = solve_roller(m, d, geo, e, 0, ring, L.cage_speed_rad_s, scale);
    F[2] += Z * r.F_ring[2];
    for (int j = 1; j < Z; ++j) d.rollers[j] = d.rollers[0];
  } else {
    for (int j = 0; j < Z; ++j) {
      // a cold start: from the loaded neighbour's equilibrium (its azimuth is one pitch away;
      // solve_roller writes every other field of the state)
      if (chain && j > 0 && d.rollers[j - 1].inner_N > 0.0) d.rollers[j] = d.rollers[j - 1];
      const RollerEval r = solve_roller(m, d, geo, e, j, ring, L.cage_speed_rad_s, scale);
      F += r.F_ring;
      M += r.M_ring;
    }
  }
  const double Lr = m.values().pitch_radius_m;
  Eigen::Matrix<double, 5, 1> res;
  res << F[0], F[1], F[2], M[0] / Lr, M[1] / Lr;
  return res;
}


}  // namespace

BearingModel::BearingModel(const BearingModelValues& v)
    : v_(validated(v)),
      profile_(v.profile),
      inner_(v.slices, v.roller_length_m, nominal_reduced_radii(v, RollerProfile(v.profile), RacewaySide::Inner),
             v.E_reduced_Pa, v.method),
      outer_(v.slices, v.roller_length_m, nominal_reduced_radii(v, RollerProfile(v.profile), RacewaySide::Outer),
             v.E_reduced_Pa, v.method) {
  // principal relative radii of the rib contact from the gap on a stencil at the nominal pose
  const Eigen::Vector3d M(v.pitch_radius_m, 0.0, v.roller_mid_z_m);
  const Eigen::Vector3d a(std::sin(v.roller_axis_angle_rad), 0.0, std::cos(v.roller_axis_angle_rad));
  const double h = 1e-4;
  double st[9];
  Eigen::Vector3d p, n;
  rib_gap(roller_end(M, a), rib_face(), 3, 3, h, h, st, p, n);
  rib_Rx_ = h * h / (st[1] + st[7] - 2 * st[4]);
  rib_Ry_ = h * h / (st[3] + st[5] - 2 * st[4]);
  if (!(rib_Rx_ > 0.0) || !(rib_Ry_ > 0.0)) {
    throw std::invalid_argument("BearingModel: the roller end and the rib do not form a convex contact");
  }
  rib_ref_ = hertz_point_contact_approach(rib_Rx_, rib_Ry_, v.E_reduced_Pa, 1e-6);
}

HertzEllipse BearingModel::rib_hertz(double approach_m) const noexcept {
  if (!(approach_m > 0.0)) return {};
  const double s = approach_m / rib_ref_.approach_m, r = std::sqrt(s);
  HertzEllipse h = rib_ref_;
  h.approach_m = approach_m;
  h.load_N *= s * r;
  h.semi_major_m *= r;
  h.semi_minor_m *= r;
  h.max_pressure_Pa *= r;
  return h;
}

RollerPose BearingModel::roller_pose(int j, double u, double w, double tilt) const noexcept {
  const double psi = 2.0 * kPi * j / v_.roller_count;
  RollerPose p;
  p.e_r = Eigen::Vector3d(std::cos(psi), std::sin(psi), 0.0);
  p.e_t = Eigen::Vector3d(-std::sin(psi), std::cos(psi), 0.0);
  const Eigen::Vector3d ez = Eigen::Vector3d::UnitZ();
  p.M = (v_.pitch_radius_m + u) * p.e_r + (v_.roller_mid_z_m + w) * ez;
  p.a = Eigen::AngleAxisd(tilt, p.e_t) *
        (std::sin(v_.roller_axis_angle_rad) * p.e_r + std::cos(v_.roller_axis_angle_rad) * ez);
  return p;
}

RollerEnd BearingModel::roller_end(const Eigen::Vector3d& M, const Eigen::Vector3d& a) const noexcept {
  return {M + v_.end_sphere_offset_m * a, a, v_.end_sphere_radius_m, v_.end_cap_radius_m};
}

RibFace BearingModel::rib_face() const noexcept {
  return {{v_.rib_apex_z_m, v_.rib_half_angle_rad}, v_.rib_outer_radius_m};
}

double BearingModel::rib_closest(const Eigen::Vector3d& M, const Eigen::Vector3d& a, Eigen::Vector3d& p_RC,
                                 Eigen::Vector3d& n_R) const noexcept {
  double h0 = 0.0;  // a one-cell grid: only the closest point and its gap are wanted
  return rib_gap(roller_end(M, a), rib_face(), 1, 1, 1e-6, 1e-6, &h0, p_RC, n_R);
}

BearingData::BearingData(const BearingModel& m)
    : rollers(m.values().roller_count),
      geo_(m.values().slices),
      e_(2 * m.values().slices) {
  for (int j = 0; j < m.values().roller_count; ++j) {
    inner_lines.emplace_back(m.inner_line());
    outer_lines.emplace_back(m.outer_line());
  }
}

int solve_load_distribution(const BearingModel& m, BearingData& d, const BearingLoads& L) noexcept {
  if (!std::isfinite(L.axial_N) || !std::isfinite(L.radial_N) || !std::isfinite(L.tilt_moment_Nm) ||
      !std::isfinite(L.cage_speed_rad_s) || !std::isfinite(L.misalignment_x_rad) ||
      !std::isfinite(L.misalignment_y_rad) || L.axial_N < 0.0 || L.radial_N < 0.0 ||
      (L.axial_N == 0.0 && L.radial_N == 0.0 && !L.axial_offset_controlled))
    return -1;
  const auto& v = m.values();
  if (L.axial_offset_controlled && !(std::isfinite(L.axial_offset_m) && L.axial_offset_m > 0.0)) return -1;
  // unknowns: dx, dy, dz, rx, ry; the axial offset and an imposed tilt remove their DOF, and an
  // axisymmetric load keeps the ring centred
  d.symmetric = L.radial_N == 0.0 && !L.tilt_free && L.tilt_moment_Nm == 0.0 && L.misalignment_x_rad == 0.0 &&
                 L.misalignment_y_rad == 0.0;
  int idx[5], ndof = 0;
  for (int k = 0; k < 5; ++k) {
    if (k == 2 && L.axial_offset_controlled) continue;
    if (k >= 3 && !L.tilt_free) continue;
    if (k < 2 && d.symmetric) continue;
    idx[ndof++] = k;
  }
  const double l = v.roller_length_m;
  const double Fa_est = L.axial_offset_controlled
                            ? v.roller_count * std::sin(v.cup_angle_rad) * palmgren_stiffness(l) *
                                  std::pow(0.5 * L.axial_offset_m * std::sin(v.cup_angle_rad), 10.0 / 9.0)
                            : L.axial_N;
  // The load scale of the residuals: the applied loads, and at least the rollers' centrifugal
  // forces, which the cup carries whatever the preload. A light displacement-controlled preload
  // (an axial offset of 1e-12 m) has a Palmgren estimate of 1e-10 N while the rollers carry
  // 79 N: the roller tolerance (1e-11 of the scale) lay below the line contacts' round-off, and
  // the roller equilibrium gate failed at 1e-5 of that scale.
  const double centrifugal_N = v.roller_count * v.roller_mass_kg * L.cage_speed_rad_s * L.cage_speed_rad_s *
                               v.pitch_radius_m;
  const double scale =
      std::max(Fa_est + L.radial_N + std::abs(L.tilt_moment_Nm) / v.pitch_radius_m, centrifugal_N);
  Eigen::Matrix<double, 5, 1> x = d.ring;
  const bool cold = !d.has_solution;
  double drop = 0.0;
  if (cold) {
    // start: Palmgren approaches for the mean roller loads of the axial and the radial share
    const double Qa = Fa_est / (v.roller_count * std::sin(v.cup_angle_rad));
    const double Qr = 4.08 * L.radial_N / (v.roller_count * std::cos(v.cup_angle_rad));
    // plus the profile drop at the slice nearest the roller's middle: a crowned roller touches
    // there first, and under a light load Palmgren's approach alone leaves every slice out of
    // contact (no residual gradient to start Newton from)
    drop = 1e300;
    for (int i = 0; i < v.slices; ++i) drop = std::min(drop, m.profile().drop_m(m.outer_line().position_m(i)));
    const double da = 2.0 * (palmgren_approach_m(Qa + 0.5 * Qr, l) + drop);
    x.setZero();
    x[2] = -da / std::sin(v.cup_angle_rad);
    x[0] = L.radial_N > 0.0 ? 2.0 * palmgren_approach_m(Qr, l) / std::cos(v.cup_angle_rad) : 0.0;
  }
  if (L.axial_offset_controlled) x[2] = -L.axial_offset_m;
  if (!L.tilt_free && (x[3] != L.misalignment_x_rad || x[4] != L.misalignment_y_rad)) {
    // An imposed tilt turns the ring about the origin of its frame, which lies far from the
    // rollers (10 mrad moved the cone's raceway by about 0.3 mm there). Along a sweep, tilt the
    // ring about the rollers' mid-plane centre c instead, so that the raceway stays where the
    // last solution had it: t += (R_old - R_new) c.
    const Eigen::Vector3d c(0.0, 0.0, v.roller_mid_z_m);
    const Eigen::Matrix3d R_old = ring_pose(x).R;
    x[3] = L.misalignment_x_rad;
    x[4] = L.misalignment_y_rad;
    const Eigen::Vector3d dt = (R_old - ring_pose(x).R) * c;
    x[0] += dt[0];
    x[1] += dt[1];
    if (!L.axial_offset_controlled) x[2] += dt[2];  // an imposed axial offset stays as given
  }
  // cold under a radial load or a tilt: the rigid ring's balance (RigidRing)
  RigidRing rigid;
  rigid.Z = v.roller_count;
  rigid.sa = std::sin(v.cup_angle_rad);
  rigid.ca = std::cos(v.cup_angle_rad);
  rigid.r_p = v.pitch_radius_m;
  rigid.z_M = v.roller_mid_z_m;
  rigid.drop = drop;
  rigid.R = ring_pose(x).R;
  const bool rigid_start = cold && !L.axial_offset_controlled && (L.radial_N > 0.0 || x[3] != 0.0 || x[4] != 0.0);
  auto apply_rigid = [&](double K, double n) {
    Eigen::Vector3d t = x.head<3>();
    if (!rigid_ring_start(rigid, K, n, Fa_est, L.radial_N, t)) return false;
    x.head<3>() = t;
    return true;
  };
  if (rigid_start) apply_rigid(palmgren_stiffness(l), 10.0 / 9.0);
  auto residual = [&](const Eigen::Matrix<double, 5, 1>& xx, Eigen::Matrix<double, 5, 1>& out) {
    out = ring_residual(m, d, d.geo_, d.e_, xx, L, scale);
  };
  if (d.symmetric) x[0] = x[1] = 0.0;
  Eigen::Matrix<double, 5, 1> full = ring_residual(m, d, d.geo_, d.e_, x, L, scale, cold);
  if (rigid_start) {
    // Palmgren's line contact is stiffer than the crowned roller's own (about 3 times at 6 kN):
    // refit Q = K dc^n to the rollers' cup loads at the start (a least-squares line in
    // logarithms over the rollers on both rings; n = 10/9 when their approaches span too
    // little) and solve the rigid ring's balance again
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, t0 = 0.0, t1 = 0.0, lo = 1e300, hi = 0.0;
    Eigen::Vector3d e;
    for (int j = 0; j < v.roller_count; ++j) {
      const double dc = rigid.contact_approach(j, x.head<3>(), e);
      if (!(dc > 0.0) || !(d.rollers[j].inner_N > 0.0) || !(d.rollers[j].outer_N > 0.0)) continue;
      const double X = std::log(dc), Y = std::log(d.rollers[j].outer_N);
      s0 += 1.0;
      s1 += X;
      s2 += X * X;
      t0 += Y;
      t1 += X * Y;
      lo = std::min(lo, dc);
      hi = std::max(hi, dc);
    }
    if (s0 >= 1.0) {
      double n = 10.0 / 9.0;
      if (s0 >= 3.0 && hi > 1.2 * lo) n = std::clamp((s0 * t1 - s1 * t0) / (s0 * s2 - s1 * s1), 1.0, 2.0);
      if (apply_rigid(std::exp((t0 - n * s1) / s0), n)) full = ring_residual(m, d, d.geo_, d.e_, x, L, scale, true);
    }
  }
  auto active = [&](const Eigen::Matrix<double, 5, 1>& f) {
    Eigen::VectorXd a(ndof);
    for (int k = 0; k < ndof; ++k) a[k] = f[idx[k]];
    return a;
  };
  int status = 1;
  d.iterations = 0;
  bool fresh_needed = false;
  const Eigen::Matrix<double, 5, 1> h = (Eigen::Matrix<double, 5, 1>() << 1e-9, 1e-9, 1e-9, 1e-8, 1e-8).finished();
  constexpr double kLimMin = 10e-6, kLimMax = 320e-6;  // the ring's step limit [m] (tilt: times r_p)
  double lim = kLimMin;
  for (int it = 0; it < 100; ++it) {
    ++d.iterations;
    // 1e-8 of the load, 100 times inside the plausibility gate (1e-6): the slice solvers stop at
    // 1e-10 of their line loads, and summed over the rollers that leaves a residual noise of
    // ~1e-10 of the load (at 1e-10 the chord Newton sometimes spent 5 ... 16 iterations on that
    // noise; 1e-9 cost about one ring iteration in three more than 1e-8, for no change in the
    // torque's 7th digit)
    if (ndof == 0 || active(full).cwiseAbs().maxCoeff() <= 1e-8 * scale) {
      status = 0;
      break;
    }
    const std::vector<RollerState> base = d.rollers;
    int mask = 0;
    for (int c = 0; c < ndof; ++c) mask |= 1 << idx[c];
    const bool reuse = d.ring_jacobian_mask_ == mask && !fresh_needed;
    if (!reuse) {
      d.ring_jacobian_.resize(ndof, ndof);
      d.roller_sensitivity_.assign(base.size(), Eigen::Matrix<double, 3, 5>::Zero());
      Eigen::Matrix<double, 5, 1> fp;
      for (int c = 0; c < ndof; ++c) {
        d.rollers = base;
        Eigen::Matrix<double, 5, 1> xp = x;
        xp[idx[c]] += h[idx[c]];
        residual(xp, fp);
        d.ring_jacobian_.col(c) = (active(fp) - active(full)) / h[idx[c]];
        for (size_t j = 0; j < base.size(); ++j)
          d.roller_sensitivity_[j].col(idx[c]) =
              Eigen::Vector3d(d.rollers[j].u_m - base[j].u_m, d.rollers[j].w_m - base[j].w_m,
                              d.rollers[j].tilt_rad - base[j].tilt_rad) / h[idx[c]];
      }
      d.rollers = base;
      d.ring_jacobian_mask_ = mask;
    }
    // the rollers' start for a ring step dxr: their state at x moved by their sensitivities
    // (first order), for the rollers that the cone carries; the ring Newton's steps otherwise
    // started every roller where it was, and a cold load distribution spent about 50 roller
    // evaluations a roller on each step. The sensitivities are those of the last fresh ring
    // Jacobian, also for the Broyden steps after it and along a sweep (once the 32216 at 10 mrad
    // lost its convergence with that, before the rigid-ring start and the downhill plateau steps;
    // now it converges, and a radial-load sweep's load distribution takes 2.1 instead of 2.8 ms
    // a point).
    auto predicted = [&](const Eigen::Matrix<double, 5, 1>& dxr) {
      d.rollers = base;
      if (d.roller_sensitivity_.size() != base.size()) return;
      for (size_t j = 0; j < base.size(); ++j) {
        if (!(base[j].inner_N > 0.0)) continue;
        const Eigen::Vector3d dy = d.roller_sensitivity_[j] * dxr;
        if (!dy.allFinite()) continue;
        d.rollers[j].u_m += dy[0];
        d.rollers[j].w_m += dy[1];
        d.rollers[j].tilt_rad += dy[2];
      }
    };
    const Eigen::MatrixXd& J = d.ring_jacobian_;
    Eigen::VectorXd dx = J.fullPivLu().solve(-active(full));
    if (!dx.allFinite()) {
      if (!reuse) return 1;
      fresh_needed = true;
      continue;
    }
    double s = 1.0;
    for (int c = 0; c < ndof; ++c) s = std::max(s, std::abs(dx[c]) * (idx[c] >= 3 ? v.pitch_radius_m : 1.0) / lim);
    dx /= s;
    double step = 1.0;
    const double n0 = active(full).norm();
    Eigen::Matrix<double, 5, 1> fn, dx5 = Eigen::Matrix<double, 5, 1>::Zero();  // the step in all 5 DOF
    for (int c = 0; c < ndof; ++c) dx5[idx[c]] = dx[c];
    predicted(dx5);
    residual(x + dx5, fn);
    if (reuse && active(fn).norm() > (1.0 - 0.8 / s) * n0) {
      // the reused Jacobian no longer serves (less than 80 % of the reduction that its linear
      // model promised for this step, which the step limit shortens by 1 / s): a fresh one
      d.rollers = base;
      fresh_needed = true;
      continue;
    }
    for (int b = 0; b < 20 && active(fn).norm() >= n0; ++b) {
      step *= 0.5;
      predicted(step * dx5);
      residual(x + step * dx5, fn);
    }
    fresh_needed = false;
    // the step limit as a trust radius: doubled after a limited step that was taken whole and
    // cut the residual, halved (down to 10 um) after a step that had to be shortened. Fixed at
    // 10 um, the 32216 at 10 mrad walked 130 um to its solution in 30 iterations.
    if (step < 1.0) lim = std::max(0.5 * lim, kLimMin);
    else if (s > 1.0 && active(fn).norm() < 0.9 * n0) lim = std::min(2.0 * lim, kLimMax);
    x += step * dx5;
    // Broyden's update: the stored Jacobian takes the secant of this step, so the chord steps
    // converge superlinearly where the stiffness changes along the path (a Jacobian taken far
    // from the solution otherwise contracted the residual by only 0.1 ... 0.4 per step)
    {
      const Eigen::VectorXd s_x = step * dx;
      const Eigen::VectorXd y = active(fn) - active(full);
      const double ss = s_x.squaredNorm();
      if (ss > 0.0 && y.allFinite()) d.ring_jacobian_ += (y - d.ring_jacobian_ * s_x) * s_x.transpose() / ss;
    }
    full = fn;
  }
  d.ring = x;
  d.residual = ndof ? active(full).cwiseAbs().maxCoeff() / scale : 0.0;
  // the moment of the rollers on the ring (about x and y), scaled back from the residual form
  const double Lr = v.pitch_radius_m;
  d.reaction_moment_Nm = Eigen::Vector2d(full[3] * Lr, full[4] * Lr - L.tilt_moment_Nm);
  // residual z = -Fa_applied + (axial force of the rollers on the ring): the carried axial force
  d.axial_force_N = full[2] + (L.axial_offset_controlled ? 0.0 : L.axial_N);
  d.has_solution = true;
  return status;
}

}  // namespace kegel
