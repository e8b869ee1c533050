// Friction of the whole bearing at a solved load distribution (see quasi_static.hpp).
#include <algorithm>
#include <cmath>
#include <vector>

#include <memory>

#include "kegel/core/cell_contact.hpp"
#include "kegel/core/contact_geometry.hpp"
#include "kegel/core/hertz.hpp"
#include "kegel/core/quasi_static.hpp"

namespace kegel {
namespace {
constexpr double kPi = 3.14159265358979323846;

// One loaded contact point of a roller, in the inertial frame R.
struct Point {
  Eigen::Vector3d p, n, t_roll, t_line;  // contact point, normal (ring -> roller), tangents
  double load_N = 0.0, width_m = 0.0, R_m = 0.0;
  int contact = 0;                        // BearingFriction::Contact
  double rib_Rx = 0.0, rib_Ry = 0.0, rib_area = 0.0, rib_contact_load = 0.0;
};

struct Roller {
  Eigen::Vector3d M, a, et;
  double radius = 0.0;  // roller mid radius, where it touches the pocket walls
  std::vector<Point> points;
};

// Forces of all contact points of a roller for spin w_R and cage speed w_c: returns the spin
// moment about the roller axis and the moment about the bearing axis (which the cage pocket
// takes: the cage is in balance when these sum to zero); optionally accumulates the
// torques on the rings and the mechanism powers.
struct Eval {
  double spin_moment = 0.0;
  double axis_moment = 0.0;  // moment of the contact loads on the roller about the bearing axis
  double pocket_N = 0.0;     // normal force of the cage pocket (the roller's circumferential load)
  double pocket_W = 0.0;     // friction power in the pocket (Eq. 37)
  double torque_inner = 0.0, torque_outer = 0.0;  // moments about z of the forces on the rings
  double P[3][5] = {};
  double Lmin[3] = {1e300, 1e300, 1e300}, phimax[3] = {0, 0, 0};
};

// lub_o / lub_i: the lubricant state of the outer ring's contacts and of the inner ring's (its
// raceway and its rib).
Eval eval(const Roller& r, double w_R, double w_c, double w_i, const ContactLubricantState& lub_o,
          const ContactLubricantState& lub_i, const FrictionParameters& fp, const SurfacePair& race,
          const SurfacePair& rib, bool accumulate, bool cage) {
  Eval e;
  double tangential = 0.0;  // circumferential load of the contacts on the roller
  const Eigen::Vector3d ez = Eigen::Vector3d::UnitZ();
  for (const Point& c : r.points) {
    // surface velocities relative to the cage (where the contact is) and sliding
    const Eigen::Vector3d u1 = w_R * r.a.cross(c.p - r.M);
    const double w_ring_rel = c.contact == BearingFriction::kOuter ? -w_c : w_i - w_c;
    const Eigen::Vector3d u2 = w_ring_rel * ez.cross(c.p);
    SliceResult s;
    if (c.contact == BearingFriction::kRib) {
      CellInput in;
      in.load_N = c.load_N;
      in.contact_load_N = c.rib_contact_load;
      in.area_m2 = c.rib_area;
      in.Rx_m = c.rib_Rx;
      in.Ry_m = c.rib_Ry;
      in.u1_x_m_s = u1.dot(c.t_roll);
      in.u1_y_m_s = u1.dot(c.t_line);
      in.u2_x_m_s = u2.dot(c.t_roll);
      in.u2_y_m_s = u2.dot(c.t_line);
      evaluate_cell(in, rib, lub_i, fp, s);  // the rib is the inner ring's
    } else {
      SliceInput in;
      in.load_N = c.load_N;
      in.width_m = c.width_m;
      in.reduced_radius_m = c.R_m;
      in.u1_x_m_s = u1.dot(c.t_roll);
      in.u1_y_m_s = u1.dot(c.t_line);
      in.u2_x_m_s = u2.dot(c.t_roll);
      in.u2_y_m_s = u2.dot(c.t_line);
      in.outer_ring = c.contact == BearingFriction::kOuter;  // its raceway's inlet supply
      evaluate_slice(in, race, in.outer_ring ? lub_o : lub_i, fp, s);
    }
    // tangential force on the roller: sliding (Eq. 36)
    const Eigen::Vector3d f = (s.F_ehl_sliding_N[0] + s.F_solid_sliding_N[0]) * c.t_roll +
                              (s.F_ehl_sliding_N[1] + s.F_solid_sliding_N[1]) * c.t_line;
    const double u1x = u1.dot(c.t_roll), u2x = u2.dot(c.t_roll);
    // rolling resistance as a moment on the pair: hysteresis (Eq. 20), solid rolling (Eq. 19) and
    // the EHL rolling force (Eq. 16) acting on both surfaces, whose dissipation F (u1 + u2) equals
    // that of the moment 2 F R' at the rolling rate u / R'. The moment acts through a shift of the
    // normal force towards the inlet by M / Q, an action-reaction pair on roller and ring.
    const double M_ehl = 2.0 * s.F_ehl_rolling_N * c.R_m;
    const double Mrr = s.M_hysteresis_Nm + s.M_solid_rolling_Nm + M_ehl;
    const double shift = c.load_N > 0.0 ? Mrr / c.load_N : 0.0;
    const double um = 0.5 * (u1x + u2x);
    const Eigen::Vector3d p_n = c.p - shift * (um >= 0 ? 1.0 : -1.0) * c.t_roll;
    const Eigen::Vector3d fn = c.load_N * c.n;
    const Eigen::Vector3d m_roller = (c.p - r.M).cross(f) + (p_n - r.M).cross(fn);
    e.spin_moment += m_roller.dot(r.a);
    e.axis_moment += (c.p.cross(f) + p_n.cross(fn)).dot(ez);
    tangential += (f + fn).dot(r.et);
    if (accumulate) {
      // forces on the ring: -(sliding), its own rolling resistance, -(normal) at the shifted point
      const double tz = c.p.cross(-f).dot(ez) + p_n.cross(-fn).dot(ez);
      if (c.contact == BearingFriction::kOuter) e.torque_outer += tz; else e.torque_inner += tz;
      const int k = c.contact;
      e.P[k][BearingFriction::kEhlSliding] += s.P_ehl_sliding_W;
      e.P[k][BearingFriction::kSolidSliding] += s.P_solid_sliding_W;
      if (Mrr > 0.0) {
        // The work the shifted normal force pair does on the two surfaces: fn . (v_ring - v_roller)
        // at p_n less its value at p, i.e. fn . ((W_ring - W_roller) x (p_n - p)) with the two
        // angular velocities relative to the cage. It equals M (u1 / R1 + u2 / R2), the moment
        // times the relative rolling rate, which is 2 F u_m = F (u1 + u2) of Eq. 16 in pure
        // rolling; under slip it differs from the laws' F (u1 + u2) when R1 != R2, and it is
        // this work that the drive pays (counting F (u1 + u2) missed the power balance by up to
        // 1.1 % in the pocket model, whose spin braking makes the rollers slip: Table 3, 11-15 kN).
        // Split among the mechanisms in proportion to their moments.
        const Eigen::Vector3d dW = w_ring_rel * ez - w_R * r.a;
        const double P_shift = fn.dot(dW.cross(p_n - c.p));
        e.P[k][BearingFriction::kEhlRolling] += P_shift * (M_ehl / Mrr);
        e.P[k][BearingFriction::kSolidRolling] += P_shift * (s.M_solid_rolling_Nm / Mrr);
        e.P[k][BearingFriction::kHysteresis] += P_shift * (s.M_hysteresis_Nm / Mrr);
      }
      if (s.in_contact) {
        e.Lmin[k] = std::min(e.Lmin[k], s.Lambda);
        e.phimax[k] = std::max(e.phimax[k], s.phi);
      }
    }
  }
  if (cage) {
    // the pocket wall takes the roller's circumferential load; its Coulomb friction (Eq. 37, the
    // same regularised mu(v)) acts where the roller surface slides on the wall at w_R * radius
    // and brakes the roller's spin
    e.pocket_N = std::abs(tangential);
    const double v = std::abs(w_R) * r.radius;
    const double mu = tribology::cubic_friction_coefficient(fp.cubic_law(), v);
    e.spin_moment -= (w_R >= 0 ? 1.0 : -1.0) * mu * e.pocket_N * r.radius;
    e.pocket_W = mu * e.pocket_N * v;
  }
  return e;
}

// (1 - t) a + t b of two evaluations (accumulated), the extremes of the film parameters of both
Eval mix(const Eval& a, const Eval& b, double t) {
  Eval e;
  const double s = 1.0 - t;
  e.spin_moment = s * a.spin_moment + t * b.spin_moment;
  e.axis_moment = s * a.axis_moment + t * b.axis_moment;
  e.pocket_N = s * a.pocket_N + t * b.pocket_N;
  e.pocket_W = s * a.pocket_W + t * b.pocket_W;
  e.torque_inner = s * a.torque_inner + t * b.torque_inner;
  e.torque_outer = s * a.torque_outer + t * b.torque_outer;
  for (int k = 0; k < 3; ++k) {
    for (int q = 0; q < 5; ++q) e.P[k][q] = s * a.P[k][q] + t * b.P[k][q];
    e.Lmin[k] = std::min(a.Lmin[k], b.Lmin[k]);
    e.phimax[k] = std::max(a.phimax[k], b.phimax[k]);
  }
  return e;
}

// Brent's method on [a, b] with f(a) f(b) <= 0.
template <class F>
bool brent(F f, double a, double b, double fa, double fb, double tol, double& root) {
  if (fa * fb > 0.0) return false;
  double c = a, fc = fa, d = b - a, e = d;
  for (int it = 0; it < 200; ++it) {
    if (fb * fc > 0.0) { c = a; fc = fa; d = e = b - a; }
    if (std::abs(fc) < std::abs(fb)) { a = b; b = c; c = a; fa = fb; fb = fc; fc = fa; }
    const double t = 2.0 * 1e-16 * std::abs(b) + 0.5 * tol, m = 0.5 * (c - b);
    if (std::abs(m) <= t || fb == 0.0) { root = b; return true; }
    if (std::abs(e) >= t && std::abs(fa) > std::abs(fb)) {
      double p, q, r, s = fb / fa;
      if (a == c) { p = 2.0 * m * s; q = 1.0 - s; }
      else { q = fa / fc; r = fb / fc; p = s * (2.0 * m * q * (q - r) - (b - a) * (r - 1.0)); q = (q - 1.0) * (r - 1.0) * (s - 1.0); }
      if (p > 0.0) q = -q; else p = -p;
      if (2.0 * p < std::min(3.0 * m * q - std::abs(t * q), std::abs(e * q))) { e = d; d = p / q; }
      else { d = m; e = d; }
    } else { d = m; e = d; }
    a = b; fa = fb;
    b += std::abs(d) > t ? d : (m > 0 ? t : -t);
    fb = f(b);
  }
  root = b;
  return false;
}

// Secant iteration from x0, x1; false when it does not converge to tol within 12 steps.
template <class F>
bool secant(F f, double x0, double x1, double tol, double& root) {
  double f0 = f(x0), f1 = f(x1);
  for (int it = 0; it < 12; ++it) {
    if (f1 == f0) return false;
    const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
    if (!std::isfinite(x2)) return false;
    x0 = x1;
    f0 = f1;
    x1 = x2;
    if (std::abs(x1 - x0) <= tol) {
      root = x1;
      return true;
    }
    f1 = f(x1);
  }
  return false;
}

// A root of f near x0: the secant from the warm start guess, else Brent on the bracket
// x0 (1 -+ rel), widened about x0 by factors of 2 (at most 30 times) until f changes sign; with
// max_dist, the secant's root and the bracket stay within max_dist of x0.
template <class F>
bool root_near(F f, double guess, double x0, double rel, double tol, double& root, double max_dist = INFINITY) {
  if (secant(f, guess, guess * (1.0 + 1e-7), tol, root) && std::abs(root - x0) <= max_dist) return true;
  const double d0 = std::min(std::abs(x0) * rel, max_dist);
  double lo = x0 - d0, hi = x0 + d0;
  double flo = f(lo), fhi = f(hi);
  for (int k = 0; k < 30 && flo * fhi > 0.0 && hi - x0 < max_dist; ++k) {
    lo = std::max(x0 + (lo - x0) * 2.0, x0 - max_dist);
    hi = std::min(x0 + (hi - x0) * 2.0, x0 + max_dist);
    flo = f(lo);
    fhi = f(hi);
  }
  return brent(f, lo, hi, flo, fhi, tol, root);
}

// one revolution of the walk from the lead x (the end lead); the shares when asked
double pocket_walk_revolution(const double* lead, const int* state, int n, double c, double x, double* share) {
  for (int k = 0; k < n; ++k) {
    double th = 0.0;
    if (state[k] == 2) {
      // unloaded: coasts with the cage
    } else if (state[k] == 1 || state[k] == -1) {
      x = state[k] * c;
      th = 1.0;
    } else {
      const double dx = lead[k], xn = x + dx;
      if (xn > c) {
        th = 1.0 - (c - x) / dx;
        x = c;
      } else if (xn < -c) {
        th = 1.0 - (-c - x) / dx;
        x = -c;
      } else {
        x = xn;
      }
    }
    if (share) share[k] = th;
  }
  return x;
}

}  // namespace

double periodic_pocket_walk(const double* lead, const int* state, int n, double half_clearance,
                            double* share) noexcept {
  const double c = half_clearance;
  double lo = -c, hi = c;
  for (int it = 0; it < 64; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (pocket_walk_revolution(lead, state, n, c, mid, nullptr) - mid > 0.0) lo = mid; else hi = mid;
  }
  const double x0 = 0.5 * (lo + hi);
  pocket_walk_revolution(lead, state, n, c, x0, share);
  return x0;
}

int evaluate_bearing_friction(const BearingModel& m, BearingData& d, const BearingLoads& L, double w_i,
                              const ContactLubricantState& lub, const FrictionParameters& fp,
                              const SurfacePair& race, const SurfacePair& ribp, BearingFriction& out,
                              int rib_cells, CageModel cage_model, RibPressure rib_pressure) noexcept {
  return evaluate_bearing_friction(m, d, L, w_i, lub, lub, fp, race, ribp, out, rib_cells, cage_model, rib_pressure);
}

int evaluate_bearing_friction(const BearingModel& m, BearingData& d, const BearingLoads& L, double w_i,
                              const ContactLubricantState& lub_o, const ContactLubricantState& lub_i,
                              const FrictionParameters& fp, const SurfacePair& race, const SurfacePair& ribp,
                              BearingFriction& out, int rib_cells, CageModel cage_model,
                              RibPressure rib_pressure) noexcept {
  bool cage = cage_model == CageModel::Pocket;  // pocket forces and friction (every roller)
  const bool walls = cage_model == CageModel::Walls;
  if (walls && !(m.values().cage_pocket_clearance_m > 0.0)) return -1;
  if (!d.has_solution || !std::isfinite(w_i) || w_i == 0.0 || rib_cells < 0 || rib_cells > 256) return -1;
  std::vector<double> rib_h0;
  std::vector<unsigned char> rib_in;  // the cells inside the rib's Hertz ellipse
  std::vector<double> rib_p;          // Hertz's pressure on the rib cells
  int out_rib_edge = 0;  // rollers whose rib ellipse an edge cuts (their cell field solved)
  const auto& v = m.values();
  const int Z = v.roller_count, n = v.slices;
  const double w = m.outer_line().width_m();
  Eigen::Matrix3d Rr =
      (Eigen::AngleAxisd(d.ring[3], Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(d.ring[4], Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  const Eigen::Vector3d dr = d.ring.head<3>();
  const RollerShape shape{v.roller_mean_radius_m, v.roller_half_angle_rad, v.roller_length_m};
  std::vector<double> xi(n), e(n);
  for (int i = 0; i < n; ++i) xi[i] = m.outer_line().position_m(i);
  std::vector<SliceGeometry> geo(n);
  std::vector<Roller> rollers(Z);
  if (rib_cells > 0) {
    // size the grid by the largest rib load of all rollers
    double q_max = 0.0;
    for (int j = 0; j < (d.symmetric ? 1 : Z); ++j) {
      const auto& st = d.rollers[j];
      const RollerPose pose = m.roller_pose(j, st.u_m, st.w_m, st.tilt_rad);
      Eigen::Vector3d pc, nc;
      const double g = m.rib_closest(Rr.transpose() * (pose.M - dr), Rr.transpose() * pose.a, pc, nc);
      if (g < 0.0) q_max = std::max(q_max, m.rib_hertz(-g).load_N);
    }
    if (q_max > 0.0) {
      const HertzEllipse hz = hertz_point_contact_load(m.rib_Rx_m(), m.rib_Ry_m(), v.E_reduced_Pa, q_max);
      const bool x_minor = m.rib_Rx_m() <= m.rib_Ry_m();
      const double dx = 6.0 * (x_minor ? hz.semi_minor_m : hz.semi_major_m) / rib_cells;
      const double dy = 6.0 * (x_minor ? hz.semi_major_m : hz.semi_minor_m) / rib_cells;
      // The grid is always the one this load calls for, so a point's result does not depend on
      // the points solved before it (reusing a grid within 20 % of the size moved the 32216's
      // torque by 1 % between a cold and a warm start at 32 x 32 cells). Its cells scale with the
      // contact, so the previous pressure fields, copied cell by cell, remain good warm starts
      // (the solver rescales them to the new load).
      const bool same = d.rib_n_ == rib_cells && dx == d.rib_dx_ && dy == d.rib_dy_;
      if (!same) {
        // one workspace (FFT plans) for all rollers, built when a roller's field is first solved
        // (Hertz's field needs none); each roller keeps its own solved pressure field, copied cell
        // by cell from the last grid as its warm start
        d.rib_grid_.reset();
        d.rib_work_.reset();
        if (int(d.rib_pressure_.size()) != Z) d.rib_pressure_.assign(Z, {});
        for (auto& pr : d.rib_pressure_)
          if (pr.size() != size_t(rib_cells) * rib_cells) pr.clear();
        d.rib_n_ = rib_cells;
        d.rib_dx_ = dx;
        d.rib_dy_ = dy;
      }
    }
  }
  // contact points at the load distribution (an axisymmetric case needs roller 0 only)
  const int Zc = d.symmetric ? 1 : Z;
  const double weight = d.symmetric ? double(Z) : 1.0;
  for (int j = 0; j < Zc; ++j) {
    Roller& r = rollers[j];
    const auto& st = d.rollers[j];
    const RollerPose pose = m.roller_pose(j, st.u_m, st.w_m, st.tilt_rad);
    r.et = pose.e_t;
    r.M = pose.M;
    r.a = pose.a;
    r.radius = v.roller_mean_radius_m;
    for (int side = 0; side < 2; ++side) {
      const bool outer = side == 0;
      const Eigen::Vector3d M = outer ? r.M : Eigen::Vector3d(Rr.transpose() * (r.M - dr));
      const Eigen::Vector3d a = outer ? r.a : Eigen::Vector3d(Rr.transpose() * r.a);
      raceway_slice_geometry(shape, m.profile(), M, a, {v.apex_z_m, outer ? v.cup_angle_rad : v.cone_angle_rad},
                             outer ? RacewaySide::Outer : RacewaySide::Inner, xi.data(), n, geo.data());
      for (int i = 0; i < n; ++i) e[i] = geo[i].interference_m;
      LineContactData& ld = outer ? d.outer_lines[j] : d.inner_lines[j];
      if (solve_line_contact(outer ? m.outer_line() : m.inner_line(), ld, e.data()) < 0) return -1;
      for (int i = 0; i < n; ++i) {
        if (!(ld.line_load_N_m[i] > 0.0)) continue;
        Point c;
        const Eigen::Matrix3d R = outer ? Eigen::Matrix3d::Identity() : Rr;
        c.p = R * geo[i].p_RC + (outer ? Eigen::Vector3d::Zero() : dr);
        c.n = R * geo[i].n_R;
        c.t_roll = R * geo[i].t_roll_R;
        c.t_line = R * geo[i].t_line_R;
        c.load_N = ld.line_load_N_m[i] * w;
        c.width_m = w;
        c.R_m = geo[i].reduced_radius_m;
        c.contact = outer ? BearingFriction::kOuter : BearingFriction::kInner;
        r.points.push_back(c);
      }
    }
    // rib, as one elliptic contact
    const Eigen::Vector3d Mi = Rr.transpose() * (r.M - dr), ai = Rr.transpose() * r.a;
    Eigen::Vector3d pc, nc;
    const double gmin = m.rib_closest(Mi, ai, pc, nc);
    if (gmin < 0.0) {
      const HertzEllipse hz = m.rib_hertz(-gmin);
      const Eigen::Vector3d p_glob = Rr * pc + dr;
      const Eigen::Vector3d er_c = Eigen::Vector3d(p_glob.x(), p_glob.y(), 0.0).normalized();
      const Eigen::Vector3d t_circ = Eigen::Vector3d::UnitZ().cross(er_c);  // circumferential
      if (rib_cells == 0) {
        Point c;
        c.p = p_glob;
        c.n = Rr * nc;
        c.t_roll = t_circ;
        c.t_line = c.n.cross(c.t_roll).normalized();  // along the rib generator
        c.load_N = hz.load_N;
        c.contact = BearingFriction::kRib;
        c.rib_Rx = m.rib_Rx_m();
        c.rib_Ry = m.rib_Ry_m();
        c.rib_area = kPi * hz.semi_major_m * hz.semi_minor_m;
        r.points.push_back(c);
      } else {
        // cell model on the bearing's rib grid (x along the rib generator, y circumferential)
        if (d.rib_n_ != rib_cells) return -1;
        const double dx = d.rib_dx_, dy = d.rib_dy_;
        const size_t nc_cells = size_t(rib_cells) * rib_cells;
        rib_p.resize(nc_cells);
        const double* pressure = rib_p.data();
        rib_h0.resize(nc_cells);  // rib_gap writes every cell
        Eigen::Vector3d pc2, nc2;
        const RollerEnd end = m.roller_end(Mi, ai);
        // Hertz's field where the ellipse lies wholly on the cap and the rib (see RibPressure):
        // a cell inside the ellipse whose gap is the far value of rib_gap (off the cap or off
        // the rib) means an edge cuts the contact. Hertz's field needs the gap inside the
        // ellipse only; the solved field needs all of it.
        const bool x_minor = m.rib_Rx_m() <= m.rib_Ry_m();
        const double ax = x_minor ? hz.semi_minor_m : hz.semi_major_m;
        const double ay = x_minor ? hz.semi_major_m : hz.semi_minor_m;
        rib_in.assign(nc_cells, 0);
        double sum = 0.0;
        for (int ix = 0; ix < rib_cells; ++ix) {
          const double x = (ix + 0.5 - 0.5 * rib_cells) * dx / ax;
          for (int iy = 0; iy < rib_cells; ++iy) {
            const double y = (iy + 0.5 - 0.5 * rib_cells) * dy / ay;
            const double rho = 1.0 - x * x - y * y;
            const size_t k = size_t(ix) * rib_cells + iy;
            const double sq = rho > 0.0 ? std::sqrt(rho) : 0.0;
            rib_p[k] = sq;
            rib_in[k] = rho > 0.0;
            sum += sq;
          }
        }
        const bool masked = rib_pressure == RibPressure::Hertz;
        rib_gap(end, m.rib_face(), rib_cells, rib_cells, dx, dy, rib_h0.data(), pc2, nc2,
                masked ? rib_in.data() : nullptr);
        const double far = 0.5 * end.sphere_radius_m;
        bool edge = false;
        for (size_t k = 0; k < nc_cells && !edge; ++k)
          if (rib_in[k] && !(rib_h0[k] < far)) edge = true;
        if (edge) ++out_rib_edge;
        // an ellipse smaller than a cell (no cell centre inside): the solved field
        const bool hertz = masked && !edge && sum > 0.0;
        if (hertz) {
          const double scale = hz.load_N / (sum * dx * dy);
          for (double& p : rib_p) p *= scale;
        } else {
          if (masked) rib_gap(end, m.rib_face(), rib_cells, rib_cells, dx, dy, rib_h0.data(), pc2, nc2);
          if (!d.rib_grid_) {
            d.rib_grid_ = std::make_shared<CellContactModel>(rib_cells, rib_cells, dx, dy, v.E_reduced_Pa);
            d.rib_work_ = std::make_shared<CellContactData>(*d.rib_grid_);
          }
          CellContactData& field = *d.rib_work_;
          std::vector<double>& warm = d.rib_pressure_[j];
          field.has_solution = !warm.empty();
          if (field.has_solution) field.pressure_Pa = warm;
          // the pressure field to 1e-6 (relative change, load-normalised), not the solver's
          // default 1e-9: a warm start then takes 8-9 conjugate-gradient steps instead of 13-16
          // (the rib cells were 40 % of a warm combined-load point), and the torque moves by
          // 6e-10 (32216, Fa 6 kN, Fr 6.5 kN, 2000 rpm)
          CellContactSettings cs;
          cs.tolerance = 1e-6;
          if (solve_cell_contact(*d.rib_grid_, field, rib_h0.data(), hz.load_N, cs) < 0) return -1;
          warm = field.pressure_Pa;
          pressure = field.pressure_Pa.data();
        }
        // tangent basis of the grid (as in rib_gap), in the ring frame
        const Eigen::Vector3d er_r = Eigen::Vector3d(pc.x(), pc.y(), 0.0).normalized();
        const Eigen::Vector3d t1 = std::cos(v.rib_half_angle_rad) * Eigen::Vector3d::UnitZ() +
                                   std::sin(v.rib_half_angle_rad) * er_r;
        const Eigen::Vector3d t2(-er_r.y(), er_r.x(), 0.0);
        for (int ix = 0; ix < rib_cells; ++ix) {
          for (int iy = 0; iy < rib_cells; ++iy) {
            const double pr = pressure[ix * rib_cells + iy];
            if (!(pr > 0.0)) continue;
            Point c;
            const Eigen::Vector3d q = pc + ((ix + 0.5 - 0.5 * rib_cells) * dx) * t1 + ((iy + 0.5 - 0.5 * rib_cells) * dy) * t2;
            c.p = Rr * q + dr;
            c.n = Rr * nc;
            c.t_roll = Rr * t2;
            c.t_line = Rr * t1;
            c.load_N = pr * dx * dy;
            c.contact = BearingFriction::kRib;
            c.rib_Rx = m.rib_Rx_m();
            c.rib_Ry = m.rib_Ry_m();
            c.rib_area = dx * dy;
            c.rib_contact_load = hz.load_N;
            r.points.push_back(c);
          }
        }
      }
    }
  }

  // pure rolling: the rolling condition at the two raceway contacts of the middle slice of a
  // roller at its nominal place (apex-matched geometry)
  {
    const Eigen::Vector3d er = Eigen::Vector3d::UnitX(), et = Eigen::Vector3d::UnitY(), ez = Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d M = v.pitch_radius_m * er + v.roller_mid_z_m * ez;
    const Eigen::Vector3d a = std::sin(v.roller_axis_angle_rad) * er + std::cos(v.roller_axis_angle_rad) * ez;
    const Eigen::Vector3d n_perp = -std::sin(v.roller_axis_angle_rad) * ez + std::cos(v.roller_axis_angle_rad) * er;
    const Eigen::Vector3d po = M + v.roller_mean_radius_m * n_perp, pi = M - v.roller_mean_radius_m * n_perp;
    const double ko = a.cross(po - M).dot(et), ki = a.cross(pi - M).dot(et);
    // outer: w_c r_o + w_R ko = 0; inner: w_c r_i + w_R ki = w_i r_i
    const double ro = po.x(), ri = pi.x();
    const double det = ro * ki - ri * ko;
    out.cage_speed_pure_rolling_rad_s = w_i * ri * ki / det;
    const double w_R0 = -out.cage_speed_pure_rolling_rad_s * ro / ko;
    out.roller_spin_pure_rolling_rad_s.assign(Z, w_R0);
  }
  const double wc0 = out.cage_speed_pure_rolling_rad_s, wR0 = out.roller_spin_pure_rolling_rad_s[0];
  out.roller_spin_rad_s.assign(Z, wR0);
  int status = 0;
  // roller j's spin that balances its spin moments when it orbits at w_c (unloaded: pure
  // rolling), with its pocket's friction when ``pocket``
  auto spin_at = [&](int j, double w_c, bool pocket) {
    const Roller& r = rollers[j];
    const double w_pure = wR0 * w_c / wc0;
    if (r.points.empty()) return w_pure;
    auto S = [&](double wr) { return eval(r, wr, w_c, w_i, lub_o, lub_i, fp, race, ribp, false, pocket).spin_moment; };
    const double tol = 1e-13 * std::abs(w_pure);
    double root = w_pure;
    // warm start from the previous slip of this roller
    if (!root_near(S, w_pure * d.spin_ratio_[j], w_pure, 0.1, tol, root)) status = 1;
    return root;
  };
  auto spin_for_cage = [&](double w_c, std::vector<double>& spins) {
    double tangential = 0.0;
    for (int j = 0; j < Zc; ++j) {
      spins[j] = spin_at(j, w_c, cage);
      if (!rollers[j].points.empty())
        tangential += weight * eval(rollers[j], spins[j], w_c, w_i, lub_o, lub_i, fp, race, ribp, false, cage).axis_moment;
    }
    for (int j = Zc; j < Z; ++j) spins[j] = spins[0];
    return tangential;
  };
  std::vector<double> spins(Z);
  if (int(d.spin_ratio_.size()) != Z) d.spin_ratio_.assign(Z, 1.0);
  // Coupled Newton on (cage speed, roller spins), warm-started from the last slips: the
  // Jacobian is an arrow (each roller's spin balance depends on its spin and the cage speed,
  // the cage balance on all), so it reduces to one scalar equation for the cage speed.
  double w_c = wc0 * d.cage_ratio_;
  for (int j = 0; j < Z; ++j) spins[j] = wR0 * (w_c / wc0) * d.spin_ratio_[j];
  double cage_residual = 0.0;
  // every roller at the cage speed: the cage speed at which the rollers' loads on the pockets
  // have no net moment about the axis, and each roller's spin in balance at it
  auto solve_common_cage = [&]() {
    bool newton_ok = false;
    w_c = wc0 * d.cage_ratio_;
    for (int j = 0; j < Z; ++j) spins[j] = wR0 * (w_c / wc0) * d.spin_ratio_[j];
    {
      // derivatives by finite differences, reused across iterations and operating points while
      // the iteration contracts (chord); recomputed when it does not
      std::vector<double> S(Zc), A(Zc);
      if (int(d.dSw_.size()) != Zc) {
        d.dSw_.assign(Zc, 1.0);
        d.dSc_.assign(Zc, 0.0);
        d.dAw_.assign(Zc, 0.0);
        d.dAc_.assign(Zc, 0.0);
        d.derivatives_valid_ = false;
      }
      std::vector<double>& Sw = d.dSw_;
      std::vector<double>& Sc = d.dSc_;
      std::vector<double>& Aw = d.dAw_;
      std::vector<double>& Ac = d.dAc_;
      const double hw = 1e-7 * std::abs(wR0), hc = 1e-7 * std::abs(wc0);
      double last_step = INFINITY;
      for (int it = 0; it < 16 && !newton_ok; ++it) {
        const bool fresh = !d.derivatives_valid_;
        double num = 0.0, den = 0.0;
        cage_residual = 0.0;
        for (int j = 0; j < Zc; ++j) {
          const Roller& r = rollers[j];
          if (r.points.empty()) {
            S[j] = A[j] = Sc[j] = Aw[j] = Ac[j] = 0.0;
            Sw[j] = 1.0;
            continue;
          }
          const Eval e0 = eval(r, spins[j], w_c, w_i, lub_o, lub_i, fp, race, ribp, false, cage);
          S[j] = e0.spin_moment;
          A[j] = weight * e0.axis_moment;
          if (fresh) {
            const Eval e1 = eval(r, spins[j] + hw, w_c, w_i, lub_o, lub_i, fp, race, ribp, false, cage);
            const Eval e2 = eval(r, spins[j], w_c + hc, w_i, lub_o, lub_i, fp, race, ribp, false, cage);
            Sw[j] = (e1.spin_moment - S[j]) / hw;
            Sc[j] = (e2.spin_moment - S[j]) / hc;
            Aw[j] = weight * (e1.axis_moment - e0.axis_moment) / hw;
            Ac[j] = weight * (e2.axis_moment - e0.axis_moment) / hc;
            if (!(std::abs(Sw[j]) > 0.0)) Sw[j] = 1.0;
          }
          num += A[j] - Aw[j] * S[j] / Sw[j];
          den += Ac[j] - Aw[j] * Sc[j] / Sw[j];
          cage_residual += A[j];
        }
        d.derivatives_valid_ = true;
        if (!(std::abs(den) > 0.0) || !std::isfinite(num / den)) break;
        const double dc = -num / den;
        std::vector<double> dw(Zc);
        double dw_max = 0.0;
        for (int j = 0; j < Zc; ++j) {
          dw[j] = rollers[j].points.empty() ? wR0 * (w_c + dc) / wc0 - spins[j] : -(S[j] + Sc[j] * dc) / Sw[j];
          dw_max = std::max(dw_max, std::abs(dw[j]) / std::abs(wR0));
        }
        const double step = std::max(std::abs(dc) / std::abs(wc0), dw_max);
        if (!fresh && step > 0.1 * last_step) {
          // the reused derivatives no longer contract well: recompute them at this iterate
          d.derivatives_valid_ = false;
          last_step = INFINITY;
          continue;
        }
        for (int j = 0; j < Zc; ++j) spins[j] += dw[j];
        w_c += dc;
        for (int j = Zc; j < Z; ++j) spins[j] = spins[0];
        last_step = step;
        if (!std::isfinite(w_c) || std::abs(w_c - wc0) > 0.5 * std::abs(wc0)) {
          d.derivatives_valid_ = false;
          break;
        }
        if (step <= 1e-12) newton_ok = true;
      }
    }
    if (!newton_ok) {
      // fallback: nested scalar root finding (secant, then Brent)
      auto C = [&](double wc) { return spin_for_cage(wc, spins); };
      w_c = wc0;
      if (!root_near(C, wc0 * d.cage_ratio_, wc0, 0.02, 1e-13 * std::abs(wc0), w_c)) status = 1;
      cage_residual = spin_for_cage(w_c, spins);
    }
  };
  // FreeRollers needs it only when no roller finds an orbit of its own (below): its own
  // solution does not depend on a common cage speed, and under a combined load the common cage
  // solve cost more than the free rollers (it often fell back to the nested root finding)
  if (cage_model != CageModel::FreeRollers && !walls) solve_common_cage();
  // FreeRollers: each loaded roller's own orbital speed and spin (two balances, 2 x 2 Newton
  // with finite-difference derivatives, warm-started), then the cage at their time-mean speed
  std::vector<double> orbit(Z, w_c);
  out.locked_rollers = 0;
  out.roller_drift_m = 0.0;
  // FreeRollers with locked rollers (loaded, but no orbit of their own: a roller on the cup
  // alone, held there by its centrifugal force, or one that barely touches the inner ring): the
  // cage drives them through their pockets at its speed, and the cage takes the moment that
  // costs from the free rollers, each pressing on its pocket with an equal share q_pocket (the
  // pocket's moment on the roller about the bearing axis), with Coulomb friction (Eq. 37) as in
  // the pocket model. The share vanishes with the locked rollers' load, so the torque is
  // continuous where a roller locks.
  std::vector<char> free(Zc, 0);
  double q_pocket = 0.0;
  bool cage_drives_locked = false;  // free rollers exist and the locked ones are driven by the cage
  auto pocket_friction = [&](const Roller& r, double wr, double q, Eval& e) {
    if (q == 0.0) return;
    const double P = std::abs(q) / std::hypot(r.M.x(), r.M.y());
    const double vs = std::abs(wr) * r.radius;
    const double mu = tribology::cubic_friction_coefficient(fp.cubic_law(), vs);
    e.spin_moment -= (wr >= 0 ? 1.0 : -1.0) * mu * P * r.radius;
    e.pocket_N = P;
    e.pocket_W = mu * P * vs;
  };
  auto eval_free = [&](const Roller& r, double wr, double wo) {
    Eval e = eval(r, wr, wo, w_i, lub_o, lub_i, fp, race, ribp, false, false);
    e.axis_moment += q_pocket;
    pocket_friction(r, wr, q_pocket, e);
    return e;
  };
  // Walls: each roller's free state, its state held at a wall, and the share of its azimuth
  // step it spends there
  std::vector<double> wall_share(Z, 0.0), wall_spin(Z, 0.0), wall_A(Z, 0.0), free_orbit, free_spin;
  bool walls_on = false;
  out.pocket_fraction = cage ? 1.0 : 0.0;
  if (cage_model == CageModel::FreeRollers || walls) {
    if (int(d.orbit_ratio_.size()) != Z) d.orbit_ratio_.assign(Z, NAN);
    if (int(d.free_spin_ratio_.size()) != Z) d.free_spin_ratio_.assign(Z, NAN);
    if (d.free_jacobian_.size() != 4 * size_t(Z)) d.free_jacobian_.assign(4 * size_t(Z), NAN);
    const double hr = 1e-7 * std::abs(wR0), ho = 1e-7 * std::abs(wc0);
    double n_free = 0.0;
    for (int pass = 0; pass < 30; ++pass) {
    out.locked_rollers = 0;
    std::fill(free.begin(), free.end(), 0);
    for (int j = 0; j < Zc; ++j) {
      const Roller& r = rollers[j];
      if (r.points.empty()) continue;
      // 2 x 2 Newton from (wo, wr), damped: a step is accepted when it reduces the Newton
      // correction (Deuflhard's natural monotonicity test, Newton Methods for Nonlinear Problems,
      // 2004, Sec. 3.3), else halved. Undamped, a warm start 0.1 % off the solution oscillated
      // between +-2 % steps for all 60 iterations (the traction saturates within a few per mil of
      // slip) before the cold start found the solution in 3 steps.
      // The derivatives are kept per roller (chord Newton, across iterations and points) while
      // a step with them halves the correction; else they are taken afresh at the iterate.
      double* J = &d.free_jacobian_[4 * size_t(j)];
      auto newton = [&](double& wo, double& wr) {
        Eval e0 = eval_free(r, wr, wo);
        for (int it = 0; it < 40; ++it) {
          bool fresh = false;
          if (!std::isfinite(J[0])) {
            const Eval e1 = eval_free(r, wr + hr, wo);
            const Eval e2 = eval_free(r, wr, wo + ho);
            J[0] = (e1.spin_moment - e0.spin_moment) / hr;
            J[1] = (e2.spin_moment - e0.spin_moment) / ho;
            J[2] = (e1.axis_moment - e0.axis_moment) / hr;
            J[3] = (e2.axis_moment - e0.axis_moment) / ho;
            fresh = true;
          }
          const double J11 = J[0], J12 = J[1], J21 = J[2], J22 = J[3];
          const double det = J11 * J22 - J12 * J21;
          if (!(std::abs(det) > 1e-12 * std::abs(J11 * J22)) || !std::isfinite(det)) {
            J[0] = NAN;
            if (fresh) return false;
            continue;
          }
          // the Newton correction of a residual, in units of the pure-rolling speeds
          auto correction = [&](const Eval& e, double& c_r, double& c_o) {
            c_r = -(J22 * e.spin_moment - J12 * e.axis_moment) / det;
            c_o = -(-J21 * e.spin_moment + J11 * e.axis_moment) / det;
            return std::hypot(c_r / wR0, c_o / wc0);
          };
          double dr, dO;
          const double m0 = correction(e0, dr, dO);
          if (!std::isfinite(m0)) {
            J[0] = NAN;
            if (fresh) return false;
            continue;
          }
          // converged at a step of 1e-12 of the pure-rolling speeds: the chord iteration
          // converges linearly, and at 1e-10 the error it left (of the order of the last step)
          // broke the torque balance by 1e-7 at 500 rpm, 100 degC, where the traction is steep
          if (std::abs(dr) <= 1e-12 * std::abs(wR0) && std::abs(dO) <= 1e-12 * std::abs(wc0)) {
            wr += dr;
            wo += dO;
            return true;
          }
          // at most 2 % of the pure-rolling speeds per step
          double lam = 1.0 / std::max({1.0, std::abs(dr) / (0.02 * std::abs(wR0)), std::abs(dO) / (0.02 * std::abs(wc0))});
          bool accepted = false;
          for (int b = 0; b < (fresh ? 12 : 1) && !accepted; ++b, lam *= 0.5) {
            const double wr_t = wr + lam * dr, wo_t = wo + lam * dO;
            if (!std::isfinite(wr_t) || !std::isfinite(wo_t) || std::abs(wo_t - wc0) > 0.5 * std::abs(wc0)) continue;
            const Eval et = eval_free(r, wr_t, wo_t);
            double cr, co;
            const double mt = correction(et, cr, co);
            if (std::isfinite(mt) && mt <= (fresh ? 1.0 - 0.25 * lam : 0.5) * m0) {
              // Broyden's update of the kept derivatives with the step's secant (in the
              // speeds scaled by their pure-rolling values), so that the chord steps converge
              // superlinearly instead of contracting by 0.3-0.5 per step
              const double sr = wr_t - wr, so = wo_t - wo;
              const double wsr = sr / (wR0 * wR0), wso = so / (wc0 * wc0), ss = sr * wsr + so * wso;
              const double y1 = et.spin_moment - e0.spin_moment - (J[0] * sr + J[1] * so);
              const double y2 = et.axis_moment - e0.axis_moment - (J[2] * sr + J[3] * so);
              if (ss > 0.0 && std::isfinite(y1) && std::isfinite(y2)) {
                J[0] += y1 * wsr / ss;
                J[1] += y1 * wso / ss;
                J[2] += y2 * wsr / ss;
                J[3] += y2 * wso / ss;
              }
              wr = wr_t;
              wo = wo_t;
              e0 = et;
              accepted = true;
            }
          }
          if (!accepted) {
            if (fresh) return false;
            J[0] = NAN;  // the kept derivatives no longer serve: fresh ones at this iterate
          }
        }
        return false;
      };
      // warm start from the last point's orbit and spin of this roller (relative to the
      // pure-rolling speeds); failing that, cold from the pure-rolling cage speed and the spin
      // balanced at it (a warm start must never decide the answer)
      double wo = wc0 * d.orbit_ratio_[j], wr = wR0 * d.free_spin_ratio_[j];
      bool ok = std::isfinite(wo) && std::isfinite(wr) && newton(wo, wr);
      if (!ok) {
        wo = wc0;
        wr = spin_at(j, wc0, false);  // the free-roller model: no pocket forces
        ok = newton(wo, wr);
      }
      if (ok) {
        spins[j] = wr;
        orbit[j] = wo;
        free[j] = 1;
        d.orbit_ratio_[j] = wo / wc0;
        d.free_spin_ratio_[j] = wr / wR0;
      } else {
        ++out.locked_rollers;
        d.orbit_ratio_[j] = d.free_spin_ratio_[j] = J[0] = NAN;
      }
    }
    // time-mean orbital speed over one revolution: the harmonic mean over the azimuths, where
    // the unloaded and the locked rollers move with the cage
    n_free = 0.0;
    double inv = 0.0;
    for (int j = 0; j < Zc; ++j) {
      if (!free[j]) continue;
      n_free += 1.0;
      inv += 1.0 / orbit[j];
    }
    if (n_free == 0.0) {
      q_pocket = 0.0;  // no free roller to pass the moment to: the common cage solve below
      break;
    }
    w_c = n_free / inv;
    if (walls) break;  // the walls, not equal shares, carry the locked rollers (below)
    // the locked rollers, driven through their pockets at the cage speed: the moment the cage
    // passes them, and the free rollers' share of it (next pass, until it no longer changes)
    double M_locked = 0.0;
    for (int j = 0; j < Zc; ++j) {
      if (free[j] || rollers[j].points.empty()) continue;
      spins[j] = spin_at(j, w_c, true);  // its pocket's friction included
      M_locked += eval(rollers[j], spins[j], w_c, w_i, lub_o, lub_i, fp, race, ribp, false, true).axis_moment;
    }
    const double q_new = M_locked / n_free;
    const double dq = q_new - q_pocket;
    q_pocket = q_new;
    if (std::abs(dq) <= 1e-10 * std::abs(q_new) + 1e-15) break;
    if (pass == 29) status = 1;
    }
    cage_drives_locked = n_free > 0.0;
    if (n_free > 0.0) {
      for (int j = 0; j < Zc; ++j) {
        if (free[j]) continue;
        // unloaded rollers: with the cage, spinning in balance at its speed; locked ones were
        // solved with their pockets above
        orbit[j] = w_c;
        if (rollers[j].points.empty()) spins[j] = spin_at(j, w_c, false);
      }
      for (int j = Zc; j < Z; ++j) {
        spins[j] = spins[0];
        orbit[j] = orbit[0];
      }
      // the roller at step k of a revolution travelled in the direction of the cage's motion
      auto roller_at_step = [Z](int k, double wc) { return wc >= 0.0 ? k : (Z - k) % Z; };
      // the accumulated lead of a roller over its pocket, travelling once round in the
      // direction of the cage's motion, from pocket azimuth to pocket azimuth
      const double step = 2.0 * kPi / Z * v.pitch_radius_m;
      double lead = 0.0, lo = 0.0, hi = 0.0;
      for (int k = 0; k < Z; ++k) {
        const int j = roller_at_step(k, w_c);
        lead += step * (1.0 - w_c / orbit[j]);
        lo = std::min(lo, lead);
        hi = std::max(hi, lead);
      }
      out.roller_drift_m = hi - lo;
      // Walls: a walk that stays inside the clearance meets no wall (the free-roller solution)
      if (walls && Zc == Z && (out.locked_rollers > 0 || out.roller_drift_m > v.cage_pocket_clearance_m)) {
        // The walk of a roller through its pocket (total circumferential clearance c), once
        // round in the direction of the cage's motion: over the azimuth step of roller j its lead
        // grows by step (1 - w_c / orbit_j) while it runs free; where it reaches a wall
        // (+-c / 2) the wall holds it at the cage's speed for the rest of the step. A locked
        // roller sits at the wall its drag presses it against. The walk is periodic (the lead
        // after one revolution equals the lead before), and the cage's speed is the one at which
        // the walls' forces, weighted by their shares, have no net moment about the axis.
        free_orbit = orbit;
        free_spin = spins;
        const double c_half = 0.5 * v.cage_pocket_clearance_m;
        // in the order of travel (the direction of the cage's motion)
        std::vector<double> lead(Z, 0.0), share_k(Z, 0.0);
        std::vector<int> state(Z, 0);
        double wall_scale = 0.0;  // sum of |share A| of the last evaluation: the residual's scale
        auto hold = [&](int j, double wc) {  // roller j held at a wall at the cage speed wc
          wall_spin[j] = spin_at(j, wc, true);
          wall_A[j] = eval(rollers[j], wall_spin[j], wc, w_i, lub_o, lub_i, fp, race, ribp, false, true).axis_moment;
        };
        // the net wall moment on the cage at the cage speed wc, the walk periodic
        auto net_wall_moment = [&](double wc) {
          const double s = wc >= 0.0 ? 1.0 : -1.0;
          for (int k = 0; k < Z; ++k) {
            const int j = roller_at_step(k, wc);
            lead[k] = 0.0;
            if (rollers[j].points.empty()) {
              state[k] = 2;
            } else if (free[j]) {
              state[k] = 0;
              lead[k] = step * (1.0 - wc / free_orbit[j]);
            } else {
              hold(j, wc);  // locked: at the wall its drag presses it against
              state[k] = s * wall_A[j] >= 0.0 ? 1 : -1;
            }
          }
          periodic_pocket_walk(lead.data(), state.data(), Z, c_half, share_k.data());
          double sum = 0.0;
          wall_scale = 0.0;
          for (int k = 0; k < Z; ++k) {
            const int j = roller_at_step(k, wc);
            wall_share[j] = share_k[k];
            if (!(wall_share[j] > 0.0)) continue;
            if (free[j]) hold(j, wc);
            sum += wall_share[j] * wall_A[j];
            wall_scale += std::abs(wall_share[j] * wall_A[j]);
          }
          return sum;
        };
        // from the free rollers' time-mean speed, where a walk inside the clearance meets no wall
        const double w_h = w_c;
        double root = w_h;
        // a roller balance that fails at a trial cage speed of the search (far from the root)
        // does not make the point fail; the balances at the root decide (below)
        const int status_before = status;
        // (the search stays within half the pure-rolling cage speed of w_h, as the Newton
        // solves do: beyond it the trial speed would reach zero and reverse the walk)
        const bool found = net_wall_moment(w_h) == 0.0 ||
                           root_near(net_wall_moment, wc0 * d.cage_ratio_, w_h, 1e-3, 1e-13 * std::abs(wc0), root,
                                     0.5 * std::abs(wc0));
        status = found ? status_before : 1;
        w_c = root;
        cage_residual = net_wall_moment(w_c);
        // a root the secant settled on at a jump of the net moment (a locked roller changing
        // its wall) is no balance
        if (std::abs(cage_residual) > 1e-6 * wall_scale + 1e-15) status = 1;
        walls_on = true;
        double share = 0.0;
        int loaded = 0;
        for (int j = 0; j < Z; ++j) {
          const double th = wall_share[j];
          share += th;
          loaded += !rollers[j].points.empty();
          if (rollers[j].points.empty()) {
            orbit[j] = w_c;
            spins[j] = spin_at(j, w_c, false);
          } else {
            // time-mean speeds over the step
            orbit[j] = (1.0 - th) * free_orbit[j] + th * w_c;
            spins[j] = (1.0 - th) * free_spin[j] + th * wall_spin[j];
          }
        }
        out.pocket_fraction = loaded > 0 ? share / loaded : 0.0;  // of the loaded rollers' time
      }
    } else {
      // no roller orbits on its own (every loaded one locked): all at the common cage speed
      // (Walls: every one at its pocket wall, the pocket model)
      if (walls) {
        cage = true;
        out.pocket_fraction = 1.0;
      }
      solve_common_cage();
      std::fill(orbit.begin(), orbit.end(), w_c);
    }
    // the cage balance residual is zero by construction (no pocket forces)
    if (!walls_on) cage_residual = 0.0;
  }
  out.roller_orbit_rad_s = orbit;
  out.roller_wall_share = wall_share;
  out.rib_edge_rollers = d.symmetric && out_rib_edge > 0 ? Z : out_rib_edge;
  out.cage_residual_Nm = cage_residual;
  out.cage_speed_rad_s = w_c;
  out.roller_spin_rad_s = spins;
  d.cage_ratio_ = w_c / wc0;
  for (int j = 0; j < Z; ++j) d.spin_ratio_[j] = spins[j] / (wR0 * w_c / wc0);
  out.inner_speed_rad_s = w_i;

  // torques and powers at the solution
  double t_in = 0.0, t_out = 0.0;
  out.cage_power_W = 0.0;
  for (int k = 0; k < 3; ++k) {
    for (int q = 0; q < 5; ++q) out.power_W[k][q] = 0.0;
    out.Lambda_min[k] = 1e300;
    out.phi_max[k] = 0.0;
  }
  const bool free_model = cage_model == CageModel::FreeRollers;
  out.pocket_moment_free_Nm = free_model ? q_pocket : 0.0;
  for (int j = 0; j < Zc; ++j) {
    // pocket forces: every roller in the pocket model; in the free-roller model the locked
    // rollers (driven by the cage) and, when there are such, the free ones' shares
    const bool locked = free_model && cage_drives_locked && !free[j] && !rollers[j].points.empty();
    Eval ev;
    if (walls_on) {
      // Walls: the free state and the state held at a wall, weighted by the wall's share
      const double th = wall_share[j];
      if (th < 1.0) ev = eval(rollers[j], free_spin[j], free_orbit[j], w_i, lub_o, lub_i, fp, race, ribp, true, false);
      if (th > 0.0) {
        const Eval ew = eval(rollers[j], wall_spin[j], w_c, w_i, lub_o, lub_i, fp, race, ribp, true, true);
        ev = th < 1.0 ? mix(ev, ew, th) : ew;
      }
    } else {
      ev = eval(rollers[j], spins[j], orbit[j], w_i, lub_o, lub_i, fp, race, ribp, true, cage || locked);
    }
    if (free_model && free[j]) {
      pocket_friction(rollers[j], spins[j], q_pocket, ev);
      // the pocket's moment on a free roller does work at the roller's orbital speed, its
      // reaction on the cage at the cage's: the difference is lost where roller and pocket meet
      // (time-mean, the rollers' drift in their pockets)
      ev.pocket_W += q_pocket * (w_c - orbit[j]);
    }
    out.cage_power_W += weight * ev.pocket_W;
    t_in += weight * ev.torque_inner;
    t_out += weight * ev.torque_outer;
    for (int k = 0; k < 3; ++k) {
      for (int q = 0; q < 5; ++q) out.power_W[k][q] += weight * ev.P[k][q];
      out.Lambda_min[k] = std::min(out.Lambda_min[k], ev.Lmin[k]);
      out.phi_max[k] = std::max(out.phi_max[k], ev.phimax[k]);
    }
  }
  for (int k = 0; k < 3; ++k)
    if (out.Lambda_min[k] > 1e299) out.Lambda_min[k] = 0.0;
  out.drive_torque_Nm = -t_in;
  out.outer_ring_torque_Nm = t_out;
  out.power_input_W = out.drive_torque_Nm * w_i;
  double P = 0.0;
  for (int k = 0; k < 3; ++k)
    for (int q = 0; q < 5; ++q) P += out.power_W[k][q];
  out.power_dissipated_W = P + out.cage_power_W;
  (void)L;
  return status;
}

}  // namespace kegel
