// Dynamic multibody simulation (see dynamics.hpp).
#include "kegel/core/dynamics.hpp"

#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "kegel/core/checks.hpp"
#include "kegel/core/hertz.hpp"

namespace kegel {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kNormStabilisation_1_s = 100.0;  // pulls |a| and |q| back to 1 (Baumgarte)
// An interference beyond this is no physical state of a steel contact: the integrator's trial
// step went too far, and it is asked to retry with a smaller one.
constexpr double kMaxInterference_m = 2e-4;

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

Mat3 quat_to_matrix(const double* q) noexcept {
  Eigen::Quaterniond Q(q[0], q[1], q[2], q[3]);
  const double n = Q.norm();
  if (n > 0.0) Q.coeffs() /= n;
  return Q.toRotationMatrix();
}

struct CageKin {
  Vec3 p, v, w;  // centre, velocity, angular velocity in R
  Mat3 R;        // cage axes in R
  Vec3 v_at(const Vec3& x) const noexcept { return v + w.cross(x - p); }
};

// The inner ring: its frame is frame R displaced by d and tilted by R about the pivot c (on the
// axis in the roller mid-plane, where the ring's mass centre is taken): a point x_ring of the
// ring is at c + d + R (x_ring - c).
struct RingKin {
  Vec3 d, v, n;  // displacement of the pivot, its velocity, the ring's axis
  Vec3 c;        // pivot in frame R (undisplaced)
  Vec3 w_tilt;   // angular velocity of the tilt
  Mat3 R;        // tilt
  double omega = 0.0;
  Vec3 centre() const noexcept { return c + d; }
  Vec3 to_ring(const Vec3& x) const noexcept { return R.transpose() * (x - c - d) + c; }
  Vec3 from_ring(const Vec3& x) const noexcept { return R * (x - c) + c + d; }
  Vec3 v_at(const Vec3& x) const noexcept { return v + (omega * n + w_tilt).cross(x - c - d); }
};

CageKin cage_kin(const DynamicModel& m, const double* y) noexcept {
  const double* c = y + m.cage_offset();
  CageKin k;
  k.p = Vec3(c[0], c[1], c[2]);
  k.R = quat_to_matrix(c + 3);
  k.v = Vec3(c[7], c[8], c[9]);
  k.w = k.R * Vec3(c[10], c[11], c[12]);
  return k;
}

RingKin ring_kin(const DynamicModel& m, const RingDrive& drive, double t, const double* y) noexcept {
  const double* r = y + m.ring_offset();
  RingKin k;
  const Mat3 Rx = Eigen::AngleAxisd(r[6], Vec3::UnitX()).toRotationMatrix();
  k.R = Rx * Eigen::AngleAxisd(r[7], Vec3::UnitY()).toRotationMatrix();
  k.n = k.R * Vec3::UnitZ();
  k.c = Vec3(0.0, 0.0, m.bearing().values().roller_mid_z_m);
  k.d = Vec3(r[0], r[1], r[2]);
  k.v = Vec3(r[3], r[4], r[5]);
  k.w_tilt = r[8] * Vec3::UnitX() + r[9] * Rx.col(1);
  k.omega = drive.speed(t);
  return k;
}

using RollerAcc = ContactAccumulators;

int thread_id() noexcept {
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}

// Run body(j) for every roller, on up to d.threads threads when every force element allows it.
template <class Body>
void for_each_roller(const DynamicData& d, int Z, Body body) noexcept {
  bool parallel = d.threads > 1;
  for (const ForceElement* el : d.elements)
    if (!el->thread_safe()) parallel = false;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(d.threads) if (parallel)
  for (int j = 0; j < Z; ++j) body(j);
#else
  (void)parallel;
  for (int j = 0; j < Z; ++j) body(j);
#endif
}

// The roller's contacts: fills data.on_roller[j], on_cage[j], on_ring[j].
// The parts of a roller's contacts (eval_roller's mask): the outer raceway (acts on the roller
// only), the inner raceway and the rib (roller and inner ring), the cage window with gravity and
// the force elements (roller and cage). A column of the Jacobian that moves only the cage or only
// the inner ring re-evaluates only the part it changes and takes the others from the base state.
constexpr int kPartOuter = 1, kPartInner = 2, kPartCage = 4, kPartsAll = 7;

int eval_roller(const DynamicModel& m, DynamicData& d, int j, double t, const double* yr, const CageKin& cage,
                const RingKin& ring, RollerOutputs* ro, RollerAcc* acc, int mask = kPartsAll) noexcept {
  const auto& bv = m.bearing().values();
  const auto& v = m.values();
  const Vec3 p(yr[0], yr[1], yr[2]);
  Vec3 a(yr[3], yr[4], yr[5]);
  const double an = a.norm();
  if (!(an > 0.5 && an < 2.0) || !std::isfinite(an)) return 1;
  a /= an;
  const Vec3 vel(yr[6], yr[7], yr[8]);
  const Vec3 w(yr[9], yr[10], yr[11]);
  if (!p.allFinite() || !vel.allFinite() || !w.allFinite()) return -1;
  const Vec3 M = p - v.roller_com_offset_m * a;  // mid-point, where the contact geometry is defined
  auto v_roller = [&](const Vec3& x) { return Vec3(vel + w.cross(x - p)); };
  // The contacts travel with the roller around the bearing: the lubricant's entrainment and the
  // rolling speeds are taken relative to the frame that turns about the axis at the roller's
  // orbital rate (the cage frame of the quasi-static solution); sliding speeds do not depend on it.
  const double r2 = p.x() * p.x() + p.y() * p.y();
  const double w_orb = r2 > 0.0 ? (p.x() * vel.y() - p.y() * vel.x()) / r2 : 0.0;
  auto v_frame = [&](const Vec3& x) { return Vec3(w_orb * Vec3(-x.y(), x.x(), 0.0)); };
  Vec3 F = Vec3::Zero(), T = Vec3::Zero();       // on the roller, about p
  Vec3 Fc = Vec3::Zero(), Tc = Vec3::Zero();     // on the cage, about its centre
  Vec3 Fr = Vec3::Zero(), Tr = Vec3::Zero();     // on the inner ring, about its pivot
  const RollerShape shape{bv.roller_mean_radius_m, bv.roller_half_angle_rad, bv.roller_length_m};
  const int n = bv.slices;
  const double wslice = m.bearing().outer_line().width_m();
  const int tid = thread_id();
  double* e = d.e[tid].data();
  const double* xi = d.xi.data();
  SliceGeometry* geo = d.geo[tid].data();
  double max_pen = 0.0;
  int mid = n / 2;
  // each part is summed on its own (F, T and the other body's wrench), stored, and the parts are
  // added in a fixed order: a partial evaluation gives the full one's sums to the last bit
  auto flush = [&](int part) noexcept {
    DynamicData::PartWrench& pw = d.parts[3 * size_t(j) + part];
    pw.roller.force_N = F;
    pw.roller.moment_Nm = T;
    pw.other.force_N = part == 2 ? Fc : Fr;
    pw.other.moment_Nm = part == 2 ? Tc : Tr;
    F.setZero(), T.setZero(), Fc.setZero(), Tc.setZero(), Fr.setZero(), Tr.setZero();
  };

  // raceways: side 0 = outer (fixed cup), side 1 = inner (driven cone)
  for (int side = 0; side < 2; ++side) {
    const bool outer = side == 0;
    if (side == 1 && (mask & kPartOuter)) flush(0);
    if (!(mask & (outer ? kPartOuter : kPartInner))) continue;
    const Vec3 Ml = outer ? M : ring.to_ring(M);
    const Vec3 al = outer ? a : Vec3(ring.R.transpose() * a);
    raceway_slice_geometry(shape, m.bearing().profile(), Ml, al,
                           {bv.apex_z_m, outer ? bv.cup_angle_rad : bv.cone_angle_rad},
                           outer ? RacewaySide::Outer : RacewaySide::Inner, xi, n, geo);
    bool any = false;
    for (int i = 0; i < n; ++i) {
      e[i] = geo[i].interference_m;
      if (e[i] > 0.0) any = true;
      max_pen = std::max(max_pen, e[i]);
    }
    if (max_pen > kMaxInterference_m) return 1;
    LineContactData& ld = outer ? d.outer_lines[j] : d.inner_lines[j];
    if (!any) {
      std::fill(ld.line_load_N_m.begin(), ld.line_load_N_m.end(), 0.0);
      ld.force_N = 0.0;
      if (ro) (outer ? ro->outer_N : ro->inner_N) = 0.0;
      continue;
    }
    if (solve_line_contact(outer ? m.bearing().outer_line() : m.bearing().inner_line(), ld, e) < 0) return 1;
    if (ro) (outer ? ro->outer_N : ro->inner_N) = ld.force_N;
    const int k = outer ? DynamicOutputs::kOuter : DynamicOutputs::kInner;
    for (int i = 0; i < n; ++i) {
      const double q = ld.line_load_N_m[i];
      if (!(q > 0.0)) continue;
      SliceGeometry g = geo[i];
      if (!outer) {
        g.p_RC = ring.from_ring(g.p_RC);
        g.n_R = ring.R * g.n_R;
        g.t_roll_R = ring.R * g.t_roll_R;
        g.t_line_R = ring.R * g.t_line_R;
      }
      const Vec3 vf = v_frame(g.p_RC);
      const Vec3 v1 = v_roller(g.p_RC) - vf;
      const Vec3 v2 = (outer ? Vec3::Zero() : ring.v_at(g.p_RC)) - vf;
      SliceInput in = make_slice_input(g, q, wslice, v1, v2);
      in.outer_ring = outer;  // its raceway's inlet supply
      SliceResult s;
      evaluate_slice(in, m.raceway(), outer ? m.outer_lubricant() : m.inner_lubricant(), m.slice_friction(), s);
      const Vec3 ft = (s.F_ehl_sliding_N[0] + s.F_solid_sliding_N[0]) * g.t_roll_R +
                      (s.F_ehl_sliding_N[1] + s.F_solid_sliding_N[1]) * g.t_line_R;
      const double Q = in.load_N;
      const double fn_mag = std::max(Q + s.F_damping_N, 0.0);
      // rolling resistance (Biboulet-Houpert, Eq. 19, 20) as a shift of the normal force towards
      // the inlet by M / Q, as in the quasi-static model. Not clamped to the contact width: the
      // EHL rolling force is mostly the Poiseuille shear of the inlet, not a pressure-centre
      // shift, and at the corrected (Biboulet-Houpert) level its lever arm exceeds b / 2 on
      // lightly loaded slices; a clamp there applied less moment than the powers count (the
      // 32216 at 500 rpm lost 10 % of its torque and its power balance).
      const double M_ehl = 2.0 * s.F_ehl_rolling_N * g.reduced_radius_m;
      const double Mrr = s.M_hysteresis_Nm + s.M_solid_rolling_Nm + M_ehl;
      const double um = 0.5 * (in.u1_x_m_s + in.u2_x_m_s);
      const double shift = Q > 0.0 ? Mrr / Q : 0.0;
      const Vec3 pn = g.p_RC - shift * (um >= 0.0 ? 1.0 : -1.0) * g.t_roll_R;
      const Vec3 fn = fn_mag * g.n_R;
      F += ft + fn;
      T += (g.p_RC - p).cross(ft) + (pn - p).cross(fn);
      if (!outer) {
        Fr -= ft + fn;
        Tr -= (g.p_RC - ring.centre()).cross(ft) + (pn - ring.centre()).cross(fn);
      }
      if (acc) {
        // the ring's velocity relative to the roller's at the contact point and at the shifted one
        const Vec3 rel_p = (outer ? Vec3::Zero() : ring.v_at(g.p_RC)) - v_roller(g.p_RC);
        const Vec3 rel_n = (outer ? Vec3::Zero() : ring.v_at(pn)) - v_roller(pn);
        acc->contact_W += ft.dot(rel_p) + fn.dot(rel_n);
        const double tz = outer ? (g.p_RC.cross(-ft) + pn.cross(-fn)).dot(Vec3::UnitZ())
                                : -((g.p_RC - ring.centre()).cross(-ft) + (pn - ring.centre()).cross(-fn)).dot(ring.n);
        acc->torque[k] += tz;
        acc->P[k][BearingFriction::kEhlSliding] += s.P_ehl_sliding_W;
        acc->P[k][BearingFriction::kSolidSliding] += s.P_solid_sliding_W;
        if (Mrr > 0.0) {
          // the work of the shifted normal force: fn . (v_ring - v_roller) at pn less its value at
          // p (the normal approach, counted by the damping and the elastic energy), split among
          // the mechanisms by their moments, as in the quasi-static model. It is M times the
          // pair's relative rolling rate; the pure-rolling rate (|u1| + |u2|) / (2 R') counted
          // before missed it under slip: the power balance was off by the cage slip (-0.34 % at
          // 1 kN on the 32208 at 2000 rpm, -41 % at 50 N)
          const double P_shift = fn.dot(rel_n - rel_p);
          acc->P[k][BearingFriction::kEhlRolling] += P_shift * (M_ehl / Mrr);
          acc->P[k][BearingFriction::kSolidRolling] += P_shift * (s.M_solid_rolling_Nm / Mrr);
          acc->P[k][BearingFriction::kHysteresis] += P_shift * (s.M_hysteresis_Nm / Mrr);
        }
        acc->damping_W += s.F_damping_N * in.normal_velocity_m_s;
        acc->Lmin[k] = std::min(acc->Lmin[k], s.Lambda);
        acc->phimax[k] = std::max(acc->phimax[k], s.phi);
      }
      if (ro && i == mid) (outer ? ro->sliding_outer_m_s : ro->sliding_inner_m_s) = in.u1_x_m_s - in.u2_x_m_s;
    }
  }

  // rib: one elliptic Hertz contact with its friction (Eq. 31-35)
  if (mask & kPartInner) {
    const Vec3 Mi = ring.to_ring(M), ai = ring.R.transpose() * a;
    Vec3 pc, nc;
    const double gmin = m.bearing().rib_closest(Mi, ai, pc, nc);
    if (ro) ro->rib_N = 0.0;
    if (gmin < 0.0) {
      if (-gmin > kMaxInterference_m) return 1;
      max_pen = std::max(max_pen, -gmin);
      const HertzEllipse hz = m.rib_contact(-gmin);
      const Vec3 pw = ring.from_ring(pc), nw = ring.R * nc;
      Vec3 troll = ring.n.cross(pw - ring.centre());
      troll -= troll.dot(nw) * nw;
      const double tn = troll.norm();
      if (tn > 0.0) troll /= tn;
      const Vec3 tline = nw.cross(troll);
      const Vec3 v1 = v_roller(pw) - v_frame(pw), v2 = ring.v_at(pw) - v_frame(pw);
      CellInput in;
      in.load_N = hz.load_N;
      in.area_m2 = kPi * hz.semi_major_m * hz.semi_minor_m;
      in.Rx_m = m.bearing().rib_Rx_m();
      in.Ry_m = m.bearing().rib_Ry_m();
      in.u1_x_m_s = v1.dot(troll);
      in.u1_y_m_s = v1.dot(tline);
      in.u2_x_m_s = v2.dot(troll);
      in.u2_y_m_s = v2.dot(tline);
      SliceResult s;
      evaluate_cell(in, m.rib(), m.inner_lubricant(), m.rib_friction(), s);  // the rib is the inner ring's
      const double v_app = -(v1 - v2).dot(nw);
      const double Fd = tribology::damping_coefficient(-gmin, m.rib_damping_Ns_m(), m.slice_friction().values().delta_max_m) * v_app;
      const Vec3 fn = std::max(hz.load_N + Fd, 0.0) * nw;
      const Vec3 ft = (s.F_ehl_sliding_N[0] + s.F_solid_sliding_N[0]) * troll +
                      (s.F_ehl_sliding_N[1] + s.F_solid_sliding_N[1]) * tline;
      F += ft + fn;
      T += (pw - p).cross(ft + fn);
      Fr -= ft + fn;
      Tr -= (pw - ring.centre()).cross(ft + fn);
      if (acc) acc->contact_W -= (ft + fn).dot(v_roller(pw) - ring.v_at(pw));
      if (ro) ro->rib_N = hz.load_N;
      if (acc) {
        acc->torque[DynamicOutputs::kRib] += -((pw - ring.centre()).cross(-(ft + fn))).dot(ring.n);
        acc->P[DynamicOutputs::kRib][BearingFriction::kEhlSliding] += s.P_ehl_sliding_W;
        acc->P[DynamicOutputs::kRib][BearingFriction::kSolidSliding] += s.P_solid_sliding_W;
        acc->damping_W += Fd * v_app;
        acc->Lmin[DynamicOutputs::kRib] = std::min(acc->Lmin[DynamicOutputs::kRib], s.Lambda);
        acc->phimax[DynamicOutputs::kRib] = std::max(acc->phimax[DynamicOutputs::kRib], s.phi);
      }
    }
  }

  if (mask & kPartInner) flush(1);

  // cage window: edges and end bars (cage_window_contact, documented in the header)
  if ((mask & kPartCage) && v.cage) {
    Vec3 P0, ex, ey, ez;
    m.pocket_frame(j, P0, ex, ey, ez);
    const Vec3 C = cage.p + cage.R * P0;
    const Vec3 EX = cage.R * ex, EY = cage.R * ey, EZ = cage.R * ez;
    const double L = bv.roller_length_m, tan_g = std::tan(bv.roller_half_angle_rad);
    const int np = v.cage_points;
    const double k_pt = palmgren_stiffness(L) / np;
    const double dmax = m.pocket_damping_Ns_m(), delta_max = m.slice_friction().values().delta_max_m;
    const auto& law = m.slice_friction().cubic_law();
    double cageN = 0.0;
    auto apply = [&](const Vec3& X, const Vec3& nrm, double delta, bool friction) {
      // nrm: unit normal pointing from the roller towards the cage at X
      const Vec3 vrel = v_roller(X) - cage.v_at(X);
      const double v_app = vrel.dot(nrm);
      const double damping = tribology::damping_coefficient(delta, dmax, delta_max);
      const double fn = std::max(k_pt * std::pow(delta, 10.0 / 9.0) + damping * v_app, 0.0);
      Vec3 f = -fn * nrm;  // on the roller
      const Vec3 vt = vrel - v_app * nrm;
      const double vs = vt.norm();
      double Pf = 0.0;
      if (friction && vs > 0.0) {
        const double ff = tribology::cage_friction_force_N(law, fn, vs);
        f -= ff * (vt / vs);
        Pf = ff * vs;
      }
      F += f;
      T += (X - p).cross(f);
      Fc -= f;
      if (acc) acc->contact_W -= f.dot(vrel);
      Tc += (X - cage.p).cross(-f);
      cageN += fn;
      if (acc) {
        acc->cage_W += Pf;
        acc->damping_W += damping * v_app * v_app;
      }
    };
    for (int side = -1; side <= 1; side += 2) {
      for (int kp = 0; kp < np; ++kp) {
        const double y = (kp + 0.5) * L / np - 0.5 * L;
        const Vec3 X = C + (side * m.window_half_width_m(y)) * EX + y * EY + v.cage_edge_height_m * EZ;
        const double s = (X - M).dot(a);
        if (std::abs(s) > 0.5 * L) continue;
        Vec3 r = X - M - s * a;
        const double dist = r.norm();
        const double delta = bv.roller_mean_radius_m + s * tan_g - dist;
        if (!(delta > 0.0) || !(dist > 0.0)) continue;
        if (delta > kMaxInterference_m) return 1;
        max_pen = std::max(max_pen, delta);
        apply(X, r / dist, delta, true);
      }
    }
    // end bars: planes y = +-(L/2 + axial clearance/2) against the rims of the roller's end faces
    const double Ye = 0.5 * L + 0.5 * v.cage_pocket_axial_clearance_m;
    for (int side = -1; side <= 1; side += 2) {
      const Vec3 dir = side * EY;
      Vec3 u = dir - dir.dot(a) * a;
      const double un = u.norm();
      const double rho_end = bv.roller_mean_radius_m + side * 0.5 * L * tan_g;
      const Vec3 X = M + (side * 0.5 * L) * a + (un > 1e-12 ? Vec3(rho_end * u / un) : Vec3::Zero());
      const double delta = (X - C).dot(dir) - Ye;
      if (!(delta > 0.0)) continue;
      if (delta > kMaxInterference_m) return 1;
      max_pen = std::max(max_pen, delta);
      apply(X, dir, delta, false);
    }
    if (ro) ro->cage_N = cageN;
  }

  // gravity and external force elements
  if (mask & kPartCage) F += v.roller_mass_kg * v.gravity_m_s2;
  if ((mask & kPartCage) && !d.elements.empty()) {
    BodyKinematics bk;
    bk.p_RC = p;
    bk.axis_R = a;
    bk.v_RC = vel;
    bk.w_R = w;
    ForceContext ctx{t, ring.omega, cage.w.z()};
    for (const ForceElement* el : d.elements) {
      Wrench wr;
      const int st = el->wrench(j, bk, ctx, wr);
      if (st != 0) return st;
      if (!wr.force_N.allFinite() || !wr.moment_Nm.allFinite()) return -1;
      F += wr.force_N;
      T += wr.moment_Nm;
      if (acc) acc->external_W -= wr.force_N.dot(vel) + wr.moment_Nm.dot(w);
    }
  }
  if (mask & kPartCage) flush(2);
  for (int part = 0; part < 3; ++part) {  // computed parts from this evaluation, the others from the base
    const DynamicData::PartWrench& pw = ((mask >> part) & 1) ? d.parts[3 * size_t(j) + part]
                                                                : d.base_parts[3 * size_t(j) + part];
    F += pw.roller.force_N;
    T += pw.roller.moment_Nm;
    (part == 2 ? Fc : Fr) += pw.other.force_N;
    (part == 2 ? Tc : Tr) += pw.other.moment_Nm;
  }
  if (!F.allFinite() || !T.allFinite()) return -1;
  d.on_roller[j].force_N = F;
  d.on_roller[j].moment_Nm = T;
  d.on_cage[j].force_N = Fc;
  d.on_cage[j].moment_Nm = Tc;
  d.on_ring[j].force_N = Fr;
  d.on_ring[j].moment_Nm = Tr;
  if (acc) acc->max_pen = std::max(acc->max_pen, max_pen);
  if (ro) {
    ro->spin_rad_s = (w - cage.w).dot(a);
    const Vec3 er = Vec3(M.x(), M.y(), 0.0).normalized();
    const Vec3 et = Vec3::UnitZ().cross(er);
    const double beta = bv.roller_axis_angle_rad;
    const Vec3 n0 = std::cos(beta) * er - std::sin(beta) * Vec3::UnitZ();
    ro->skew_rad = std::asin(std::clamp(a.dot(et), -1.0, 1.0));
    ro->tilt_rad = std::asin(std::clamp(a.dot(n0), -1.0, 1.0));
  }
  return 0;
}

// d/dt of one roller's 12 states from its wrench
void roller_derivative(const DynamicModel& m, const double* yr, const Wrench& wr, double* f) noexcept {
  const auto& v = m.values();
  Vec3 a(yr[3], yr[4], yr[5]);
  const double a2 = a.squaredNorm();
  const Vec3 an = a / std::sqrt(a2);
  const Vec3 vel(yr[6], yr[7], yr[8]), w(yr[9], yr[10], yr[11]);
  const Vec3 adot = w.cross(an) - kNormStabilisation_1_s * (a2 - 1.0) * a;
  const Vec3 acc = wr.force_N / v.roller_mass_kg;
  const double Ia = v.roller_inertia_axial_kgm2, It = v.roller_inertia_transverse_kgm2;
  const Vec3 rhs = wr.moment_Nm - (Ia - It) * an.dot(w) * w.cross(an);
  const double along = an.dot(rhs);
  const Vec3 wdot = (rhs - along * an) / It + (along / Ia) * an;
  for (int i = 0; i < 3; ++i) {
    f[i] = vel[i];
    f[3 + i] = adot[i];
    f[6 + i] = acc[i];
    f[9 + i] = wdot[i];
  }
}

// the cage's 13 derivatives from the summed wrench (about its centre, frame R)
void cage_derivative(const DynamicModel& m, const double* yc, const Vec3& F, const Vec3& T, double* f) noexcept {
  const auto& v = m.values();
  const Eigen::Quaterniond q(yc[3], yc[4], yc[5], yc[6]);
  const double q2 = q.squaredNorm();
  const Mat3 R = quat_to_matrix(yc + 3);
  const Vec3 wb(yc[10], yc[11], yc[12]);
  // q' = 1/2 q (x) (0, w_body)
  const Eigen::Quaterniond wq(0.0, wb.x(), wb.y(), wb.z());
  const Eigen::Quaterniond qd = q * wq;
  const double lam = kNormStabilisation_1_s * (q2 - 1.0);
  f[0] = yc[7];
  f[1] = yc[8];
  f[2] = yc[9];
  f[3] = 0.5 * qd.w() - lam * yc[3];
  f[4] = 0.5 * qd.x() - lam * yc[4];
  f[5] = 0.5 * qd.y() - lam * yc[5];
  f[6] = 0.5 * qd.z() - lam * yc[6];
  const Vec3 acc = F / v.cage_mass_kg + v.gravity_m_s2;
  const Vec3 Ib(v.cage_inertia_transverse_kgm2, v.cage_inertia_transverse_kgm2, v.cage_inertia_axial_kgm2);
  const Vec3 Tb = R.transpose() * T;
  const Vec3 gyro = wb.cross(Ib.cwiseProduct(wb));
  for (int i = 0; i < 3; ++i) {
    f[7 + i] = acc[i];
    f[10 + i] = (Tb[i] - gyro[i]) / Ib[i];
  }
}

// Translation: m d'' = F. Tilt (small angles a = rx, b = ry; n = (b, -a, 1)): the angular
// momentum I_a w n + I_t (a', b', 0) of the spinning ring gives
//   I_t a'' = M_x - I_a (w b' + w' b),   I_t b'' = M_y + I_a (w a' + w' a)
// (the gyroscopic moments), about the pivot; the spin itself is prescribed.
void ring_derivative(const DynamicModel& m, const RingDrive& drive, double t, const double* yi, const Vec3& F_rollers,
                     const Vec3& M_rollers, double* f) noexcept {
  const auto& v = m.values();
  const bool free_[3] = {drive.free_x, drive.free_y, drive.free_z};
  const Vec3 Fext(drive.radial(t), 0.0, -drive.axial(t));
  const Vec3 acc = (F_rollers + Fext) / v.ring_mass_kg + v.gravity_m_s2;
  for (int i = 0; i < 3; ++i) {
    f[i] = free_[i] ? yi[3 + i] : 0.0;
    f[3 + i] = free_[i] ? acc[i] : 0.0;
  }
  if (drive.tilt_free) {
    const double w = drive.speed(t), wd = drive.acceleration(t);
    const double Ia = v.ring_inertia_axial_kgm2, It = v.ring_inertia_transverse_kgm2;
    const double Mx = M_rollers.x() + drive.tilt_moment_x_Nm, My = M_rollers.y() + drive.tilt_moment_y_Nm;
    f[6] = yi[8];
    f[7] = yi[9];
    f[8] = (Mx - Ia * (w * yi[9] + wd * yi[7])) / It;
    f[9] = (My + Ia * (w * yi[8] + wd * yi[6])) / It;
  } else {
    f[6] = f[7] = f[8] = f[9] = 0.0;
  }
}

int external_on_cage(const DynamicModel& m, DynamicData& d, double t, const CageKin& cage, double omega_i, Vec3& F,
                     Vec3& T, double* external_W) noexcept {
  (void)m;
  if (d.elements.empty()) return 0;
  BodyKinematics bk;
  bk.p_RC = cage.p;
  bk.axis_R = cage.R.col(2);
  bk.v_RC = cage.v;
  bk.w_R = cage.w;
  ForceContext ctx{t, omega_i, cage.w.z()};
  for (const ForceElement* el : d.elements) {
    Wrench wr;
    const int st = el->wrench(-1, bk, ctx, wr);
    if (st != 0) return st;
    if (!wr.force_N.allFinite() || !wr.moment_Nm.allFinite()) return -1;
    F += wr.force_N;
    T += wr.moment_Nm;
    if (external_W) *external_W -= wr.force_N.dot(cage.v) + wr.moment_Nm.dot(cage.w);
  }
  return 0;
}

double perturbation(int local, double y) noexcept {
  // local index within a body block: typical magnitudes of positions, axes, velocities, rates
  static const double typ[4] = {1e-3, 1.0, 1.0, 10.0};
  return 1e-7 * std::max(std::abs(y), typ[std::min(local / 3, 3)]);
}

}  // namespace

// ------------------------------------------------------------------------------------------
DragElement::DragElement(const DragElementValues& v) : v_(v) {
  using namespace detail;
  constexpr const char* o = "DragElementValues";
  require_nonnegative(o, "oil_density_kg_m3", v.oil_density_kg_m3);
  require_nonnegative(o, "roller_drag_coefficient", v.roller_drag_coefficient);
  require_nonnegative(o, "roller_frontal_area_m2", v.roller_frontal_area_m2);
  require_range(o, "swirl_ratio", v.swirl_ratio, -2.0, 2.0);
  require_nonnegative(o, "roller_spin_drag_Nms", v.roller_spin_drag_Nms);
  require_nonnegative(o, "cage_drag_Nms", v.cage_drag_Nms);
  require_nonnegative(o, "cage_drag_Nms2", v.cage_drag_Nms2);
}

int DragElement::wrench(int body, const BodyKinematics& k, const ForceContext& ctx, Wrench& out) const noexcept {
  if (body < 0) {
    const double wz = k.w_R.z();
    out.moment_Nm = Vec3(0.0, 0.0, -v_.cage_drag_Nms * wz - v_.cage_drag_Nms2 * std::abs(wz) * wz);
    return 0;
  }
  const Vec3 v_oil = (v_.swirl_ratio * ctx.cage_speed_rad_s) * Vec3::UnitZ().cross(k.p_RC);
  const Vec3 u = k.v_RC - v_oil;
  out.force_N = -0.5 * v_.oil_density_kg_m3 * v_.roller_drag_coefficient * v_.roller_frontal_area_m2 * u.norm() * u;
  // the spin relative to the cage frame, where the oil around the rollers turns
  const double spin = (k.w_R - ctx.cage_speed_rad_s * Vec3::UnitZ()).dot(k.axis_R);
  out.moment_Nm = -v_.roller_spin_drag_Nms * spin * k.axis_R;
  return 0;
}

// ------------------------------------------------------------------------------------------
namespace {
double piecewise(const std::vector<double>& ts, const std::vector<double>& vs, double t) noexcept {
  const size_t n = std::min(ts.size(), vs.size());
  if (n == 0) return 0.0;
  if (t <= ts[0]) return vs[0];
  for (size_t i = 1; i < n; ++i)
    if (t <= ts[i]) return vs[i - 1] + (t - ts[i - 1]) / (ts[i] - ts[i - 1]) * (vs[i] - vs[i - 1]);
  return vs[n - 1];
}
}  // namespace

double RingDrive::speed(double t) const noexcept { return piecewise(time_s, speed_rad_s, t); }

double RingDrive::axial(double t) const noexcept {
  return load_time_s.empty() ? axial_N : piecewise(load_time_s, axial_profile_N, t);
}

double RingDrive::radial(double t) const noexcept {
  return load_time_s.empty() ? radial_N : piecewise(load_time_s, radial_profile_N, t);
}

double RingDrive::acceleration(double t) const noexcept {
  const size_t n = std::min(time_s.size(), speed_rad_s.size());
  for (size_t i = 1; i < n; ++i)
    if (t > time_s[i - 1] && t <= time_s[i]) return (speed_rad_s[i] - speed_rad_s[i - 1]) / (time_s[i] - time_s[i - 1]);
  return 0.0;
}

// ------------------------------------------------------------------------------------------
namespace {
FrictionParameters with_damping(const FrictionParameters& fp, double d_max) {
  FrictionParameters::Values v = fp.values();
  v.d_max_Ns_m = d_max;
  return FrictionParameters(v);
}

const DynamicValues& validated(const DynamicValues& v) {
  using namespace detail;
  constexpr const char* o = "DynamicValues";
  require_positive(o, "roller_mass_kg", v.roller_mass_kg);
  require_positive(o, "roller_inertia_axial_kgm2", v.roller_inertia_axial_kgm2);
  require_positive(o, "roller_inertia_transverse_kgm2", v.roller_inertia_transverse_kgm2);
  require_finite(o, "roller_com_offset_m", v.roller_com_offset_m);
  require_positive(o, "cage_mass_kg", v.cage_mass_kg);
  require_positive(o, "cage_inertia_axial_kgm2", v.cage_inertia_axial_kgm2);
  require_positive(o, "cage_inertia_transverse_kgm2", v.cage_inertia_transverse_kgm2);
  require_positive(o, "cage_pitch_radius_m", v.cage_pitch_radius_m);
  require_nonnegative(o, "cage_pocket_clearance_m", v.cage_pocket_clearance_m);
  require_nonnegative(o, "cage_pocket_axial_clearance_m", v.cage_pocket_axial_clearance_m);
  require_nonnegative(o, "cage_edge_height_m", v.cage_edge_height_m);
  require_positive(o, "ring_mass_kg", v.ring_mass_kg);
  require_positive(o, "ring_inertia_axial_kgm2", v.ring_inertia_axial_kgm2);
  require_positive(o, "ring_inertia_transverse_kgm2", v.ring_inertia_transverse_kgm2);
  require_nonnegative(o, "damping_time_s", v.damping_time_s);
  if (!v.gravity_m_s2.allFinite()) fail(o, "gravity_m_s2", v.gravity_m_s2.norm(), "finite components");
  if (v.cage_points < 2 || v.cage_points > 50) fail(o, "cage_points", v.cage_points, "2..50");
  return v;
}
}  // namespace

DynamicModel::DynamicModel(std::shared_ptr<const BearingModel> bearing, const DynamicValues& values,
                           const FrictionParameters& friction, const SurfacePair& raceway, const SurfacePair& rib,
                           const ContactLubricantState& lubricant)
    : DynamicModel(std::move(bearing), values, friction, raceway, rib, lubricant, lubricant) {}

DynamicModel::DynamicModel(std::shared_ptr<const BearingModel> bearing, const DynamicValues& values,
                           const FrictionParameters& friction, const SurfacePair& raceway, const SurfacePair& rib,
                           const ContactLubricantState& outer_lubricant,
                           const ContactLubricantState& inner_lubricant)
    : bearing_(std::move(bearing)),
      v_(validated(values)),
      fp_slice_(friction),
      fp_rib_(friction),
      race_(raceway),
      rib_(rib),
      lub_outer_(outer_lubricant),
      lub_inner_(inner_lubricant) {
  if (!bearing_) throw std::invalid_argument("DynamicModel: bearing model is null");
  const auto& bv = bearing_->values();
  if (v_.cage_edge_height_m >= bv.roller_mean_radius_m - bv.roller_length_m * std::tan(bv.roller_half_angle_rad))
    detail::fail("DynamicValues", "cage_edge_height_m", v_.cage_edge_height_m,
                 "below the roller's small-end radius (the window edges must touch the roller)");
  // Parametric damping (Eq. 2): d_max of each contact element = damping time x its contact
  // stiffness dQ/ddelta at delta_max (stiffness-proportional damping).
  const double dm = friction.values().delta_max_m;
  const double tau = v_.damping_time_s;
  const double k_slice = bearing_->outer_line().slice_stiffness();
  fp_slice_ = with_damping(friction, tau * 10.0 / 9.0 * k_slice * std::pow(dm, 1.0 / 9.0));
  d_pocket_ = tau * 10.0 / 9.0 * palmgren_stiffness(bv.roller_length_m) / v_.cage_points * std::pow(dm, 1.0 / 9.0);
  const HertzEllipse hz = hertz_point_contact_approach(bearing_->rib_Rx_m(), bearing_->rib_Ry_m(), bv.E_reduced_Pa, dm);
  d_rib_ = tau * 1.5 * hz.load_N / dm;
  // the rib's radii are fixed: Q = c delta^1.5 and a, b ~ Q^(1/3) (Hertz), so the elliptic
  // integrals are evaluated once here and not in every right-hand side
  rib_ref_ = hz;
  fp_rib_ = with_damping(friction, 0.0);
  // the windows must hold the roller: their edges below the roller's radius at both ends
  for (double y : {-0.5 * bv.roller_length_m, 0.5 * bv.roller_length_m})
    if (!(window_half_width_m(y) > 0.0))
      detail::fail("DynamicValues", "cage_edge_height_m", v_.cage_edge_height_m, "a window that holds the roller");
}

HertzEllipse DynamicModel::rib_contact(double delta_m) const noexcept {
  HertzEllipse h;
  if (!(delta_m > 0.0) || !(rib_ref_.approach_m > 0.0)) return h;
  const double s = delta_m / rib_ref_.approach_m;
  h.approach_m = delta_m;
  h.load_N = rib_ref_.load_N * s * std::sqrt(s);
  const double c = std::sqrt(s);  // a, b ~ Q^(1/3) = delta^(1/2)
  h.semi_major_m = rib_ref_.semi_major_m * c;
  h.semi_minor_m = rib_ref_.semi_minor_m * c;
  h.max_pressure_Pa = rib_ref_.max_pressure_Pa * c;
  h.ellipticity = rib_ref_.ellipticity;
  return h;
}

void DynamicModel::pocket_frame(int k, Vec3& centre, Vec3& e_x, Vec3& e_y, Vec3& e_z) const noexcept {
  const auto& bv = bearing_->values();
  const double psi = 2.0 * kPi * k / bv.roller_count;
  const Vec3 er(std::cos(psi), std::sin(psi), 0.0);
  e_x = Vec3(-er.y(), er.x(), 0.0);
  const double beta = bv.roller_axis_angle_rad;
  e_y = std::sin(beta) * er + std::cos(beta) * Vec3::UnitZ();
  e_z = e_x.cross(e_y);
  centre = v_.cage_pitch_radius_m * er;  // relative to the cage centre (0, 0, z_M)
}

double DynamicModel::window_half_width_m(double y) const noexcept {
  const auto& bv = bearing_->values();
  const double rho = bv.roller_mean_radius_m + y * std::tan(bv.roller_half_angle_rad) + 0.5 * v_.cage_pocket_clearance_m;
  const double h = v_.cage_edge_height_m;
  return rho > h ? std::sqrt(rho * rho - h * h) : 0.0;
}

DynamicData::DynamicData(const DynamicModel& model, int n_threads) {
  const int Z = model.roller_count();
  const auto& bv = model.bearing().values();
  threads = std::max(1, std::min(n_threads, 64));
#ifndef _OPENMP
  threads = 1;
#endif
  inner_lines.assign(Z, LineContactData(model.bearing().inner_line()));
  outer_lines.assign(Z, LineContactData(model.bearing().outer_line()));
  on_roller.assign(Z, Wrench{});
  on_cage.assign(Z, Wrench{});
  on_ring.assign(Z, Wrench{});
  base_cage.assign(Z, Wrench{});
  base_ring.assign(Z, Wrench{});
  parts.assign(3 * size_t(Z), PartWrench{});
  base_parts.assign(3 * size_t(Z), PartWrench{});
  last_y.assign(model.state_size(), 0.0);
  geo.assign(threads, std::vector<SliceGeometry>(bv.slices));
  e.assign(threads, std::vector<double>(bv.slices, 0.0));
  acc.assign(Z, ContactAccumulators{});
  status.assign(Z, 0);
  xi.resize(bv.slices);
  for (int i = 0; i < bv.slices; ++i) xi[i] = model.bearing().outer_line().position_m(i);
}

// ------------------------------------------------------------------------------------------
namespace {
// The right-hand side. out: the sums of the outputs (accumulators), with the per-roller outputs
// when roller_outputs; mask: the parts of every roller's contacts evaluated (eval_roller), the
// others taken from data.base_parts (the Jacobian's columns of the cage and the inner ring).
int rhs_impl(const DynamicModel& m, DynamicData& d, const RingDrive& drive, double t, const double* y, double* ydot,
             DynamicOutputs* out, bool roller_outputs, int mask) noexcept {
  const int Z = m.roller_count();
  d.last_valid = false;
  for (int i = 0, N = m.state_size(); i < N; ++i)
    if (!std::isfinite(y[i])) return -1;
  const CageKin cage = cage_kin(m, y);
  const RingKin ring = ring_kin(m, drive, t, y);
  RollerAcc acc;
  RollerAcc* pacc = out ? &acc : nullptr;
  if (out && roller_outputs) out->rollers.resize(Z);
  Vec3 Fc = Vec3::Zero(), Tc = Vec3::Zero(), Fr = Vec3::Zero(), Tr = Vec3::Zero();
  for_each_roller(d, Z, [&](int j) {
    if (out) d.acc[j] = RollerAcc{};
    d.status[j] = eval_roller(m, d, j, t, y + 12 * j, cage, ring, out && roller_outputs ? &out->rollers[j] : nullptr,
                              out ? &d.acc[j] : nullptr, mask);
    if (d.status[j] == 0) roller_derivative(m, y + 12 * j, d.on_roller[j], ydot + 12 * j);
  });
  for (int j = 0; j < Z; ++j) {  // in roller order: the sums do not depend on the threads
    if (d.status[j] != 0) return d.status[j];
    Fc += d.on_cage[j].force_N;
    Tc += d.on_cage[j].moment_Nm;
    Fr += d.on_ring[j].force_N;
    Tr += d.on_ring[j].moment_Nm;
    if (out) {
      const RollerAcc& a = d.acc[j];
      for (int k = 0; k < 3; ++k) {
        for (int q = 0; q < 5; ++q) acc.P[k][q] += a.P[k][q];
        acc.Lmin[k] = std::min(acc.Lmin[k], a.Lmin[k]);
        acc.phimax[k] = std::max(acc.phimax[k], a.phimax[k]);
        acc.torque[k] += a.torque[k];
      }
      acc.damping_W += a.damping_W;
      acc.cage_W += a.cage_W;
      acc.external_W += a.external_W;
      acc.contact_W += a.contact_W;
      acc.max_pen = std::max(acc.max_pen, a.max_pen);
    }
  }
  const int st = external_on_cage(m, d, t, cage, ring.omega, Fc, Tc, pacc ? &pacc->external_W : nullptr);
  if (st != 0) return st;
  cage_derivative(m, y + m.cage_offset(), Fc, Tc, ydot + m.cage_offset());
  ring_derivative(m, drive, t, y + m.ring_offset(), Fr, Tr, ydot + m.ring_offset());
  if (out) {
    const auto& v = m.values();
    out->time_s = t;
    out->inner_speed_rad_s = ring.omega;
    out->cage_speed_rad_s = cage.w.z();
    for (int k = 0; k < 3; ++k) {
      out->Lambda_min[k] = acc.Lmin[k] > 1e299 ? 0.0 : acc.Lmin[k];
      out->phi_max[k] = acc.phimax[k];
      out->torque_by_contact_Nm[k] = acc.torque[k];
      for (int q = 0; q < 5; ++q) out->power_W[k][q] = acc.P[k][q];
    }
    out->outer_ring_torque_Nm = acc.torque[DynamicOutputs::kOuter];
    out->drive_torque_Nm = acc.torque[DynamicOutputs::kInner] + acc.torque[DynamicOutputs::kRib];
    out->power_input_W = out->drive_torque_Nm * ring.omega;
    out->damping_power_W = acc.damping_W;
    out->cage_power_W = acc.cage_W;
    out->external_power_W = acc.external_W;
    out->max_penetration_m = acc.max_pen;
    out->contact_work_W = acc.contact_W;
    out->ring_force_N = Fr;
    out->ring_moment_Nm = Tr;
    double E = 0.0;
    for (int j = 0; j < Z; ++j) {
      const double* yr = y + 12 * j;
      const Vec3 a = Vec3(yr[3], yr[4], yr[5]).normalized();
      const Vec3 vel(yr[6], yr[7], yr[8]), w(yr[9], yr[10], yr[11]);
      const double wa = w.dot(a);
      E += 0.5 * v.roller_mass_kg * vel.squaredNorm() + 0.5 * v.roller_inertia_axial_kgm2 * wa * wa +
           0.5 * v.roller_inertia_transverse_kgm2 * (w - wa * a).squaredNorm();
    }
    const double* yc = y + m.cage_offset();
    const Vec3 wb(yc[10], yc[11], yc[12]);
    E += 0.5 * v.cage_mass_kg * Vec3(yc[7], yc[8], yc[9]).squaredNorm() +
         0.5 * (v.cage_inertia_transverse_kgm2 * (wb.x() * wb.x() + wb.y() * wb.y()) +
                v.cage_inertia_axial_kgm2 * wb.z() * wb.z());
    const double* yi = y + m.ring_offset();
    E += 0.5 * v.ring_mass_kg * Vec3(yi[3], yi[4], yi[5]).squaredNorm() +
         0.5 * v.ring_inertia_transverse_kgm2 * (yi[8] * yi[8] + yi[9] * yi[9]);
    out->kinetic_energy_J = E;
  }
  for (int i = 0, N = m.state_size(); i < N; ++i)
    if (!std::isfinite(ydot[i])) return 1;
  if (mask == kPartsAll) {
    std::copy(y, y + m.state_size(), d.last_y.begin());
    d.last_t = t;
    d.last_valid = true;
  }
  return 0;
}
}  // namespace

int dynamic_rhs(const DynamicModel& m, DynamicData& d, const RingDrive& drive, double t, const double* y, double* ydot,
                DynamicOutputs* out) noexcept {
  return rhs_impl(m, d, drive, t, y, ydot, out, out != nullptr, kPartsAll);
}

int dynamic_jacobian(const DynamicModel& m, DynamicData& d, const RingDrive& drive, double t, const double* y,
                     const double* f0, double* J, double* work, int ld) noexcept {
  const int N = m.state_size(), Z = m.roller_count();
  const int oc = m.cage_offset(), oi = m.ring_offset();
  if (ld < N) ld = N;
  std::fill(J, J + size_t(ld) * ld, 0.0);
  // work: [0, N) perturbed state, [N, 2N) derivative
  double* yp = work;
  double* fp = work + N;
  // base per-roller contributions at y: those of the last evaluation when it was at y (CVODE
  // asks for the Jacobian at the state whose derivative it has just evaluated)
  int st = 0;
  if (!(d.last_valid && d.last_t == t && std::equal(y, y + N, d.last_y.begin()))) {
    st = rhs_impl(m, d, drive, t, y, fp, nullptr, false, kPartsAll);
    if (st != 0) return st;
  }
  d.last_valid = false;  // the columns below overwrite the per-roller contributions
  std::copy(d.on_cage.begin(), d.on_cage.end(), d.base_cage.begin());
  std::copy(d.on_ring.begin(), d.on_ring.end(), d.base_ring.begin());
  std::copy(d.parts.begin(), d.parts.end(), d.base_parts.begin());
  const auto& base_cage = d.base_cage;
  const auto& base_ring = d.base_ring;
  const CageKin cage = cage_kin(m, y);
  const RingKin ring = ring_kin(m, drive, t, y);
  const auto& v = m.values();
  const bool free_[3] = {drive.free_x, drive.free_y, drive.free_z};
  const Vec3 Ib(v.cage_inertia_transverse_kgm2, v.cage_inertia_transverse_kgm2, v.cage_inertia_axial_kgm2);
  // roller columns, coloured: column c of every roller at once
  std::copy(y, y + N, yp);
  for (int c = 0; c < 12; ++c) {
    for_each_roller(d, Z, [&](int j) {
      const int col = 12 * j + c;
      const double h = perturbation(c, y[col]);
      double yr[12];
      std::copy(y + 12 * j, y + 12 * j + 12, yr);
      yr[c] += h;
      d.status[j] = eval_roller(m, d, j, t, yr, cage, ring, nullptr, nullptr);
      if (d.status[j] != 0) return;
      double fr[12];
      roller_derivative(m, yr, d.on_roller[j], fr);
      double* Jc = J + size_t(col) * ld;
      for (int r = 0; r < 12; ++r) Jc[12 * j + r] = (fr[r] - f0[12 * j + r]) / h;
      if (v.cage) {
        const Vec3 dF = (d.on_cage[j].force_N - base_cage[j].force_N) / h;
        const Vec3 dT = cage.R.transpose() * (d.on_cage[j].moment_Nm - base_cage[j].moment_Nm) / h;
        for (int r = 0; r < 3; ++r) {
          Jc[oc + 7 + r] = dF[r] / v.cage_mass_kg;
          Jc[oc + 10 + r] = dT[r] / Ib[r];
        }
      }
      const Vec3 dFr = (d.on_ring[j].force_N - base_ring[j].force_N) / h;
      for (int r = 0; r < 3; ++r)
        if (free_[r]) Jc[oi + 3 + r] = dFr[r] / v.ring_mass_kg;
      if (drive.tilt_free) {
        const Vec3 dMr = (d.on_ring[j].moment_Nm - base_ring[j].moment_Nm) / h;
        Jc[oi + 8] = dMr.x() / v.ring_inertia_transverse_kgm2;
        Jc[oi + 9] = dMr.y() / v.ring_inertia_transverse_kgm2;
      }
    });
    for (int j = 0; j < Z; ++j)
      if (d.status[j] != 0) return d.status[j];
  }
  // cage and ring columns, one by one. A cage column changes only the cage-window part of each
  // roller's contacts, a ring column only the inner-raceway and rib part: the other parts are the
  // base state's. The columns of a held ring translation or tilt are left zero: their states do
  // not change (zero rows), so the Newton corrections never use them.
  for (int col = oc; col < N; ++col) {
    const bool in_cage = col < oi;
    const int k = in_cage ? col - oc : col - oi;
    if (!in_cage && ((k < 6 && !free_[k % 3]) || (k >= 6 && !drive.tilt_free))) continue;
    const int local = in_cage ? (k < 3 ? 0 : k < 7 ? 3 : k < 10 ? 6 : 9) : (k < 3 ? 0 : k < 6 ? 6 : k < 8 ? 3 : 9);
    const double h = perturbation(local, y[col]);
    yp[col] = y[col] + h;
    st = rhs_impl(m, d, drive, t, yp, fp, nullptr, false, in_cage ? kPartCage : kPartInner);
    yp[col] = y[col];
    if (st != 0) return st;
    double* Jc = J + size_t(col) * ld;
    for (int r = 0; r < N; ++r) Jc[r] = (fp[r] - f0[r]) / h;
  }
  return 0;
}

std::vector<double> initial_state(const DynamicModel& m, const BearingData& qs, double cage_speed,
                                  const std::vector<double>& spin) {
  const int Z = m.roller_count();
  if (static_cast<int>(qs.rollers.size()) != Z)
    throw std::invalid_argument("initial_state: the quasi-static data belong to another bearing");
  if (!spin.empty() && static_cast<int>(spin.size()) != Z)
    throw std::invalid_argument("initial_state: roller_spin_rad_s needs one value per roller");
  std::vector<double> y(m.state_size(), 0.0);
  const Vec3 ez = Vec3::UnitZ();
  for (int j = 0; j < Z; ++j) {
    const auto& r = qs.rollers[j];
    const RollerPose pose = m.bearing().roller_pose(j, r.u_m, r.w_m, r.tilt_rad);
    const Vec3 p = pose.M + m.values().roller_com_offset_m * pose.a;
    const Vec3 vel = cage_speed * ez.cross(p);
    const Vec3 w = cage_speed * ez + (spin.empty() ? 0.0 : spin[j]) * pose.a;
    for (int i = 0; i < 3; ++i) {
      y[12 * j + i] = p[i];
      y[12 * j + 3 + i] = pose.a[i];
      y[12 * j + 6 + i] = vel[i];
      y[12 * j + 9 + i] = w[i];
    }
  }
  double* c = y.data() + m.cage_offset();
  c[2] = m.bearing().values().roller_mid_z_m;
  c[3] = 1.0;
  c[12] = cage_speed;
  // the quasi-static ring pose turns about the origin of frame R: x = R x_ring + d_qs; here about
  // the pivot c: x = R (x_ring - c) + c + d, so d = d_qs + R c - c
  double* ri = y.data() + m.ring_offset();
  const Mat3 R = (Eigen::AngleAxisd(qs.ring[3], Vec3::UnitX()) * Eigen::AngleAxisd(qs.ring[4], Vec3::UnitY()))
                     .toRotationMatrix();
  const Vec3 pivot(0.0, 0.0, m.bearing().values().roller_mid_z_m);
  const Vec3 dd = Vec3(qs.ring[0], qs.ring[1], qs.ring[2]) + R * pivot - pivot;
  for (int i = 0; i < 3; ++i) ri[i] = dd[i];
  ri[6] = qs.ring[3];
  ri[7] = qs.ring[4];
  return y;
}

// ------------------------------------------------------------------------------------------
void quadrature_values(const DynamicOutputs& o, double* q) noexcept {
  q[0] = o.outer_ring_torque_Nm;
  q[1] = o.drive_torque_Nm;
  q[2] = o.power_input_W;
  for (int k = 0; k < 3; ++k)
    for (int m = 0; m < 5; ++m) q[3 + 5 * k + m] = o.power_W[k][m];
  q[18] = o.damping_power_W;
  q[19] = o.cage_power_W;
  q[20] = o.external_power_W;
  q[21] = o.cage_speed_rad_s;
  q[22] = o.torque_by_contact_Nm[0];
  q[23] = o.torque_by_contact_Nm[1];
  q[24] = o.torque_by_contact_Nm[2];
  q[25] = o.contact_work_W;
}

namespace {
// Newton matrix M = I - gamma J of the bearing in block-arrow form: each roller's 12 x 12 block
// D_j on the diagonal, coupled only to the border (cage, inner ring and anything after them),
// never to another roller (rollers do not touch each other: the coloured Jacobian leaves those
// blocks zero). LU by the Schur complement of the border,
//   S = M_bb - sum_j M_bj D_j^-1 M_jb,
// about Z (12^3 + 2 12^2 nb + 2 12 nb^2) + nb^3 flops instead of N^3 (20 times fewer for the
// 32216: Z = 16, nb = 23). Everything is sized once; setup and solve do not allocate.
struct ArrowLU {
  using Mat12 = Eigen::Matrix<double, 12, 12>;
  using Vec12 = Eigen::Matrix<double, 12, 1>;
  int Z = 0, nb = 0, n = 0;  // rollers, border size, full size
  std::vector<Eigen::PartialPivLU<Mat12>, Eigen::aligned_allocator<Eigen::PartialPivLU<Mat12>>> D;
  Eigen::MatrixXd X;  // 12 Z x nb: D_j^-1 M_jb
  Eigen::MatrixXd S;
  Eigen::PartialPivLU<Eigen::MatrixXd> Slu;
  Eigen::VectorXd rb, xb;

  ArrowLU(int Z_, int n_) : Z(Z_), nb(n_ - 12 * Z_), n(n_), D(Z_), X(12 * Z_, n_ - 12 * Z_), S(nb, nb), Slu(nb), rb(nb), xb(nb) {}

  static bool finite_pivots(const Eigen::Ref<const Eigen::MatrixXd>& lu) noexcept {
    for (Eigen::Index i = 0; i < lu.rows(); ++i)
      if (!(std::abs(lu(i, i)) > 0.0) || !std::isfinite(lu(i, i))) return false;
    return true;
  }
  // M column-major, leading dimension n. @return 0, or 1 (singular: recoverable)
  int setup(const double* Mdata) noexcept {
    Eigen::Map<const Eigen::MatrixXd> M(Mdata, n, n);
    const int o = 12 * Z;
    for (int j = 0; j < Z; ++j) {
      D[j].compute(Mat12(M.block<12, 12>(12 * j, 12 * j)));
      if (!finite_pivots(D[j].matrixLU())) return 1;
      for (int c = 0; c < nb; ++c) {
        const Vec12 col = M.block<12, 1>(12 * j, o + c);
        X.block<12, 1>(12 * j, c) = D[j].solve(col);
      }
    }
    S = M.block(o, o, nb, nb);
    for (int j = 0; j < Z; ++j) S.noalias() -= M.block(o, 12 * j, nb, 12) * X.block(12 * j, 0, 12, nb);
    Slu.compute(S);
    return finite_pivots(Slu.matrixLU()) ? 0 : 1;
  }
  int solve(const double* Mdata, double* x, const double* b) noexcept {
    Eigen::Map<const Eigen::MatrixXd> M(Mdata, n, n);
    const int o = 12 * Z;
    for (int j = 0; j < Z; ++j) Eigen::Map<Vec12>(x + 12 * j) = D[j].solve(Eigen::Map<const Vec12>(b + 12 * j));
    rb = Eigen::Map<const Eigen::VectorXd>(b + o, nb);
    for (int j = 0; j < Z; ++j) rb.noalias() -= M.block(o, 12 * j, nb, 12) * Eigen::Map<const Vec12>(x + 12 * j);
    xb = Slu.solve(rb);
    for (int j = 0; j < Z; ++j) Eigen::Map<Vec12>(x + 12 * j).noalias() -= X.block(12 * j, 0, 12, nb) * xb;
    Eigen::Map<Eigen::VectorXd>(x + o, nb) = xb;
    for (int i = 0; i < n; ++i)
      if (!std::isfinite(x[i])) return 1;
    return 0;
  }
};

// The SUNLinearSolver around ArrowLU (a direct solver on CVODE's dense matrix).
SUNLinearSolver_Type arrow_gettype(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID arrow_getid(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int arrow_initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }
int arrow_setup(SUNLinearSolver S, SUNMatrix A) {
  return static_cast<ArrowLU*>(S->content)->setup(SUNDenseMatrix_Data(A)) == 0 ? SUNLS_SUCCESS : SUNLS_LUFACT_FAIL;
}
int arrow_solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, realtype) {
  return static_cast<ArrowLU*>(S->content)->solve(SUNDenseMatrix_Data(A), N_VGetArrayPointer(x), N_VGetArrayPointer(b)) == 0
             ? SUNLS_SUCCESS
             : SUNLS_PACKAGE_FAIL_REC;
}
int arrow_free(SUNLinearSolver S) {
  if (!S) return SUNLS_SUCCESS;
  delete static_cast<ArrowLU*>(S->content);
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}
SUNLinearSolver make_arrow_solver(SUNContext ctx, int Z, int n) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) return nullptr;
  S->ops->gettype = arrow_gettype;
  S->ops->getid = arrow_getid;
  S->ops->initialize = arrow_initialize;
  S->ops->setup = arrow_setup;
  S->ops->solve = arrow_solve;
  S->ops->free = arrow_free;
  try {
    S->content = new ArrowLU(Z, n);
  } catch (...) {
    SUNLinSolFreeEmpty(S);
    return nullptr;
  }
  return S;
}
}  // namespace

struct DynamicSimulation::Impl {
  DynamicSimulation* sim = nullptr;
  SUNContext ctx = nullptr;
  N_Vector y = nullptr, atol = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  void* cvode = nullptr;
  std::vector<double> work;
  std::vector<double> rel;  // relative tolerance per state (0 for velocities and rates)
  N_Vector yQ = nullptr;
  DynamicOutputs out;
  std::string err;
  int last_rhs_status = 0;
  int n_model = 0;             // the bearing's states
  bool folded = false;         // the quadratures are states n_model .. n_model + kQuadratureCount
  double weight_scale = 1.0;   // keeps the error norm of the bearing's states what it was without them

  static int rhs(realtype t, N_Vector y, N_Vector ydot, void* user) noexcept {
    auto* self = static_cast<Impl*>(user);
    DynamicSimulation& s = *self->sim;
    double* f = N_VGetArrayPointer(ydot);
    int st = 0;
    if (self->folded) {
      st = rhs_impl(*s.model_, s.data_, s.drive_, t, N_VGetArrayPointer(y), f, &self->out, false, kPartsAll);
      if (st == 0) quadrature_values(self->out, f + self->n_model);
    } else {
      st = dynamic_rhs(*s.model_, s.data_, s.drive_, t, N_VGetArrayPointer(y), f);
    }
    self->last_rhs_status = st;
    return st;
  }
  // Error weights: relative and absolute for positions, axes and the quaternion; absolute only
  // for velocities and rates. The traction of an EHL contact changes by ~1e5 N per m/s of
  // sliding: a relative tolerance on a 5 m/s orbital velocity would let the sliding speed, and
  // with it the friction torque, wander by rtol x 5 m/s; an absolute one bounds it directly.
  static int weights(N_Vector y, N_Vector ewt, void* user) noexcept {
    auto* self = static_cast<Impl*>(user);
    const double* yv = N_VGetArrayPointer(y);
    const double* av = N_VGetArrayPointer(self->atol);
    double* w = N_VGetArrayPointer(ewt);
    const int N = self->n_model;
    for (int i = 0; i < N; ++i) {
      const double tol = self->rel[i] * std::abs(yv[i]) + av[i];
      if (!(tol > 0.0)) return -1;
      w[i] = self->weight_scale / tol;
    }
    // the quadratures (folded into the state) take no part in the error test, as CVODES'
    // quadratures without error control did not
    for (int i = N, n = static_cast<int>(N_VGetLength(ewt)); i < n; ++i) w[i] = 0.0;
    return 0;
  }
  // time integrals of the torques and powers (quadratures): exact means over any interval
  static int quad(realtype t, N_Vector y, N_Vector yQdot, void* user) noexcept {
    auto* self = static_cast<Impl*>(user);
    DynamicSimulation& s = *self->sim;
    const int st = dynamic_rhs(*s.model_, s.data_, s.drive_, t, N_VGetArrayPointer(y), self->work.data(), &self->out);
    if (st != 0) return st;
    quadrature_values(self->out, N_VGetArrayPointer(yQdot));
    return 0;
  }
  static int jac(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void* user, N_Vector, N_Vector, N_Vector) noexcept {
    auto* self = static_cast<Impl*>(user);
    DynamicSimulation& s = *self->sim;
    return dynamic_jacobian(*s.model_, s.data_, s.drive_, t, N_VGetArrayPointer(y), N_VGetArrayPointer(fy),
                            SUNDenseMatrix_Data(J), self->work.data(), static_cast<int>(SUNDenseMatrix_Rows(J)));
  }
  static void on_error(int code, const char* module, const char* function, char* msg, void* user) noexcept {
    auto* self = static_cast<Impl*>(user);
    try {
      std::ostringstream os;
      os << module << "." << function << " (" << code << "): " << msg;
      self->err = os.str();
    } catch (...) {
    }
  }
};

DynamicSimulation::DynamicSimulation(std::shared_ptr<const DynamicModel> model, const RingDrive& drive,
                                     const IntegratorSettings& s, double t0, const std::vector<double>& y0)
    : model_(std::move(model)), data_(*model_, s.threads), drive_(drive), settings_(s), t_(t0) {
  const int N = model_->state_size();
  if (static_cast<int>(y0.size()) != N)
    detail::fail("DynamicSimulation", "y0.size", double(y0.size()), "the model's state size " + std::to_string(N));
  for (double x : y0) detail::require_finite("DynamicSimulation", "y0", x);
  if (drive.time_s.size() != drive.speed_rad_s.size() || drive.time_s.empty())
    detail::fail("RingDrive", "time_s.size", double(drive.time_s.size()), "as many times as speeds, at least one");
  for (size_t i = 1; i < drive.time_s.size(); ++i)
    if (!(drive.time_s[i] > drive.time_s[i - 1])) detail::fail("RingDrive", "time_s", drive.time_s[i], "increasing times");
  for (double x : drive.speed_rad_s) detail::require_finite("RingDrive", "speed_rad_s", x);
  detail::require_nonnegative("RingDrive", "axial_N", drive.axial_N);
  detail::require_nonnegative("RingDrive", "radial_N", drive.radial_N);
  if (!drive.load_time_s.empty()) {
    const size_t n = drive.load_time_s.size();
    if (drive.axial_profile_N.size() != n || drive.radial_profile_N.size() != n)
      detail::fail("RingDrive", "axial_profile_N.size", double(drive.axial_profile_N.size()),
                   "one axial and one radial load per load time (" + std::to_string(n) + ")");
    for (size_t i = 0; i < n; ++i) {
      if (i > 0 && !(drive.load_time_s[i] > drive.load_time_s[i - 1]))
        detail::fail("RingDrive", "load_time_s", drive.load_time_s[i], "increasing times");
      detail::require_nonnegative("RingDrive", "axial_profile_N", drive.axial_profile_N[i]);
      detail::require_nonnegative("RingDrive", "radial_profile_N", drive.radial_profile_N[i]);
    }
  }
  detail::require_positive("IntegratorSettings", "rtol", s.rtol);
  impl_ = new Impl;
  impl_->sim = this;
  impl_->work.resize(2 * size_t(N));
  impl_->n_model = N;
  impl_->folded = s.quadratures_in_state;
  const int Nt = N + (impl_->folded ? kQuadratureCount : 0);
  impl_->weight_scale = std::sqrt(double(Nt) / double(N));
  impl_->out.rollers.resize(model_->roller_count());
  // the destructor does not run when the constructor throws: release() frees what was made
  if (SUNContext_Create(nullptr, &impl_->ctx) != 0) {
    release();
    throw std::runtime_error("DynamicSimulation: SUNContext_Create failed");
  }
  impl_->y = N_VNew_Serial(Nt, impl_->ctx);
  impl_->atol = N_VNew_Serial(Nt, impl_->ctx);
  if (!impl_->y || !impl_->atol) {
    release();
    throw std::runtime_error("DynamicSimulation: N_VNew_Serial failed");
  }
  N_VConst(0.0, impl_->y);
  N_VConst(0.0, impl_->atol);
  double* yv = N_VGetArrayPointer(impl_->y);
  double* av = N_VGetArrayPointer(impl_->atol);
  std::copy(y0.begin(), y0.end(), yv);
  impl_->rel.assign(N, s.rtol);
  auto set_block = [&](int off, int n_pos, int n_ax, int n_vel, int n_rate) {
    int i = off;
    for (int k = 0; k < n_pos; ++k) av[i++] = s.atol_position_m;
    for (int k = 0; k < n_ax; ++k) av[i++] = s.atol_axis;
    for (int k = 0; k < n_vel; ++k) {
      if (s.absolute_velocity_tolerance) impl_->rel[i] = 0.0;
      av[i++] = s.atol_velocity_m_s;
    }
    for (int k = 0; k < n_rate; ++k) {
      if (s.absolute_velocity_tolerance) impl_->rel[i] = 0.0;
      av[i++] = s.atol_rate_rad_s;
    }
  };
  for (int j = 0; j < model_->roller_count(); ++j) set_block(12 * j, 3, 3, 3, 3);
  set_block(model_->cage_offset(), 3, 4, 3, 3);
  set_block(model_->ring_offset(), 3, 0, 3, 0);
  {  // tilt angles and rates
    const int o = model_->ring_offset() + 6;
    av[o] = av[o + 1] = s.atol_axis;
    av[o + 2] = av[o + 3] = s.atol_rate_rad_s;
    if (s.absolute_velocity_tolerance) impl_->rel[o + 2] = impl_->rel[o + 3] = 0.0;
  }
  impl_->cvode = CVodeCreate(CV_BDF, impl_->ctx);
  if (!impl_->cvode) {
    release();
    throw std::runtime_error("DynamicSimulation: CVodeCreate failed");
  }
  int flag = CVodeInit(impl_->cvode, &Impl::rhs, t0, impl_->y);
  flag |= CVodeSetUserData(impl_->cvode, impl_);
  flag |= CVodeWFtolerances(impl_->cvode, &Impl::weights);
  flag |= CVodeSetErrHandlerFn(impl_->cvode, &Impl::on_error, impl_);
  flag |= CVodeSetMaxNumSteps(impl_->cvode, s.max_steps);
  if (s.max_step_s > 0.0) flag |= CVodeSetMaxStep(impl_->cvode, s.max_step_s);
  if (!impl_->folded) {
    impl_->yQ = N_VNew_Serial(kQuadratureCount, impl_->ctx);
    N_VConst(0.0, impl_->yQ);
    flag |= CVodeQuadInit(impl_->cvode, &Impl::quad, impl_->yQ);
    flag |= CVodeSetQuadErrCon(impl_->cvode, SUNFALSE);
  }
  impl_->A = SUNDenseMatrix(Nt, Nt, impl_->ctx);
  // the block-arrow solver needs the coloured Jacobian's structure (CVODE's own difference
  // quotients fill every block)
  impl_->LS = s.coloured_jacobian && s.structured_linear_solver
                  ? make_arrow_solver(impl_->ctx, model_->roller_count(), Nt)
                  : SUNLinSol_Dense(impl_->y, impl_->A, impl_->ctx);
  if (!impl_->LS) {
    release();
    throw std::runtime_error("DynamicSimulation: the linear solver could not be made");
  }
  flag |= CVodeSetLinearSolver(impl_->cvode, impl_->LS, impl_->A);
  if (s.coloured_jacobian) flag |= CVodeSetJacFn(impl_->cvode, &Impl::jac);
  if (s.jacobian_max_age_steps > 0) flag |= CVodeSetJacEvalFrequency(impl_->cvode, s.jacobian_max_age_steps);
  if (flag != 0) {
    release();
    throw std::runtime_error("DynamicSimulation: CVODE setup failed");
  }
}

DynamicSimulation::~DynamicSimulation() { release(); }

void DynamicSimulation::release() noexcept {
  if (!impl_) return;
  if (impl_->cvode) CVodeFree(&impl_->cvode);
  if (impl_->LS) SUNLinSolFree(impl_->LS);
  if (impl_->A) SUNMatDestroy(impl_->A);
  if (impl_->y) N_VDestroy(impl_->y);
  if (impl_->atol) N_VDestroy(impl_->atol);
  if (impl_->yQ) N_VDestroy(impl_->yQ);
  if (impl_->ctx) SUNContext_Free(&impl_->ctx);
  delete impl_;
  impl_ = nullptr;
}

void DynamicSimulation::add_element(std::shared_ptr<const ForceElement> e) {
  if (!e) throw std::invalid_argument("DynamicSimulation.add_element: element is null");
  data_.elements.push_back(e.get());
  owned_.push_back(std::move(e));
}

int DynamicSimulation::advance(double t_end) noexcept {
  if (!(t_end > t_)) return 0;
  impl_->err.clear();
  realtype tret = t_;
  const int flag = CVode(impl_->cvode, t_end, impl_->y, &tret, CV_NORMAL);
  t_ = tret;
  if (flag < 0) {
    try {
      std::ostringstream os;
      os << "CVODE failed at t = " << tret << " s (flag " << flag << "): " << impl_->err;
      if (impl_->last_rhs_status != 0)
        os << "; the right-hand side last returned " << impl_->last_rhs_status
           << (impl_->last_rhs_status > 0 ? " (interference beyond 0.2 mm or a non-finite derivative: the "
                                            "trial steps diverged)"
                                          : " (a force element failed or the state is not finite)");
      if (!data_.element_message.empty()) os << "; " << data_.element_message;
      for (const auto& e : owned_) {
        const std::string m = e->message();
        if (!m.empty()) os << "; " << m;
      }
      msg_ = os.str();
    } catch (...) {
    }
    return flag;
  }
  return 0;
}

std::vector<double> DynamicSimulation::quadratures() const {
  realtype t = 0.0;
  long n = 0;
  CVodeGetNumSteps(impl_->cvode, &n);
  if (n == 0) return q0_;  // before the first step
  if (!impl_->folded && CVodeGetQuad(impl_->cvode, &t, impl_->yQ) < 0) return q0_;
  const double* q = impl_->folded ? N_VGetArrayPointer(impl_->y) + impl_->n_model : N_VGetArrayPointer(impl_->yQ);
  std::vector<double> r(q, q + kQuadratureCount);
  for (int i = 0; i < kQuadratureCount; ++i) r[i] += q0_[i];
  return r;
}

std::vector<double> DynamicSimulation::state() const {
  const double* y = N_VGetArrayPointer(impl_->y);
  return std::vector<double>(y, y + model_->state_size());
}

DynamicOutputs DynamicSimulation::outputs() {
  DynamicOutputs out;
  std::vector<double> f(model_->state_size());
  const int st = dynamic_rhs(*model_, data_, drive_, t_, N_VGetArrayPointer(impl_->y), f.data(), &out);
  if (st < 0) throw std::runtime_error("DynamicSimulation.outputs: the state cannot be evaluated at t = " + std::to_string(t_));
  return out;
}

long DynamicSimulation::steps() const {
  long n = 0;
  CVodeGetNumSteps(impl_->cvode, &n);
  return n;
}
long DynamicSimulation::rhs_evaluations() const {
  long n = 0;
  CVodeGetNumRhsEvals(impl_->cvode, &n);
  return n;
}
long DynamicSimulation::jacobian_evaluations() const {
  long n = 0;
  CVodeGetNumJacEvals(impl_->cvode, &n);
  return n;
}
double DynamicSimulation::last_step_s() const {
  realtype h = 0.0;
  CVodeGetLastStep(impl_->cvode, &h);
  return h;
}

}  // namespace kegel
