#include "kegel/core/line_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kegel/core/checks.hpp"

namespace kegel {
namespace {
constexpr double kPi = 3.14159265358979323846;
#include "strip_table.inc"

// Palmgren (N, mm): delta = 3.84e-5 Q^0.9 / l^0.8  <=>  Q = delta^(10/9) l^(8/9) 3.84e-5^(-10/9).
// In SI (delta, l in m): Q = delta^(10/9) l^(8/9) * 3.84e-5^(-10/9) * 1e3^(10/9 + 8/9).
const double kPalmgrenSI = std::pow(3.84e-5, -10.0 / 9.0) * 1e6;

// Illinois (regula falsi with halving of the retained end's value) on a bracket f(a) f(b) < 0;
// stops when |f| <= ftol or the bracket is narrower than xtol. false: no convergence or a
// non-finite f.
template <class F>
bool illinois(F f, double a, double fa, double b, double fb, double ftol, double xtol, double& root) {
  int side = 0;
  for (int k = 0; k < 200; ++k) {
    const double x = (a * fb - b * fa) / (fb - fa);
    const double fx = f(x);
    if (!std::isfinite(fx)) return false;
    root = x;
    if (std::abs(fx) <= ftol || std::abs(b - a) <= xtol) return true;
    if ((fx > 0.0) == (fb > 0.0)) {
      b = x, fb = fx;
      if (side == 1) fa *= 0.5;
      side = 1;
    } else {
      a = x, fa = fx;
      if (side == -1) fb *= 0.5;
      side = -1;
    }
  }
  return false;
}
}  // namespace

double palmgren_approach_m(double Q, double l) noexcept {
  return 3.84e-5 * std::pow(std::max(Q, 0.0), 0.9) / std::pow(l * 1e3, 0.8) * 1e-3;
}

double palmgren_stiffness(double l) noexcept { return kPalmgrenSI * std::pow(l, 8.0 / 9.0); }

// ---------------------------------------------------------------------------------------------
RollerProfile::RollerProfile(const Values& v) : v_(v) {
  using namespace detail;
  constexpr const char* o = "RollerProfile";
  require_positive(o, "roller_diameter_m", v.roller_diameter_m);
  require_positive(o, "length_m", v.length_m);
  require_nonnegative(o, "a_p", v.a_p);
  require_nonnegative(o, "d_p_m", v.d_p_m);
  require_nonnegative(o, "k_p_m", v.k_p_m);
  require_nonnegative(o, "edge_radius_m", v.edge_radius_m);
  if (!(v.edge_radius_m < 0.5 * v.length_m)) fail(o, "edge_radius_m", v.edge_radius_m, "a value < length/2");
  if (v.a_p > 0.0) {
    require_positive(o, "c_p_m", v.c_p_m);
    const double pole = 0.5 * (v.d_p_m + v.c_p_m);
    x_lin_ = pole - v.k_p_m;
    if (!(x_lin_ > 0.5 * v.d_p_m)) fail(o, "k_p_m", v.k_p_m, "a value < c_p/2");
    if (v.k_p_m == 0.0 && pole <= 0.5 * v.length_m) {
      fail(o, "k_p_m", v.k_p_m, "> 0 when the logarithm's pole (d_p + c_p)/2 lies on the roller");
    }
    drop_lin_ = log_drop(x_lin_);
    const double u = (2.0 * x_lin_ - v.d_p_m) / v.c_p_m;
    slope_lin_ = v.a_p * v.roller_diameter_m * 2.0 * u / (1.0 - u * u) * (2.0 / v.c_p_m);
  }
}

double RollerProfile::log_drop(double ax) const noexcept {
  if (v_.a_p == 0.0 || ax <= 0.5 * v_.d_p_m) return 0.0;
  const double u = (2.0 * ax - v_.d_p_m) / v_.c_p_m;
  return -v_.a_p * v_.roller_diameter_m * std::log1p(-u * u);
}

double RollerProfile::drop_m(double x) const noexcept {
  const double ax = std::abs(x);
  double d = 0.0;
  if (v_.a_p > 0.0) d = ax <= x_lin_ ? log_drop(ax) : drop_lin_ + slope_lin_ * (ax - x_lin_);
  const double xe = 0.5 * v_.length_m - v_.edge_radius_m;
  if (ax > xe && v_.edge_radius_m > 0.0) {
    const double s = std::min(ax - xe, v_.edge_radius_m);
    d += v_.edge_radius_m - std::sqrt(v_.edge_radius_m * v_.edge_radius_m - s * s);
  }
  return d;
}

// ---------------------------------------------------------------------------------------------
double strip_influence_H(double a) noexcept {
  const double s = a < 0.0 ? -1.0 : 1.0;
  const double x = std::abs(a);
  if (x == 0.0) return 0.0;
  if (x >= kStripTableMax) {
    const double i2 = 1.0 / (x * x);
    return s * (0.5 * kPi * (std::log(4.0 * x) + 0.5) + (kPi / 32.0) * i2 - (3.0 * kPi / 512.0) * i2 * i2);
  }
  const double h = kStripTableMax / (kStripTableSize - 1);
  const int i = std::min(int(x / h), kStripTableSize - 2);
  const double t = (x - i * h) / h;
  const double t2 = t * t, t3 = t2 * t;
  const double R = (2 * t3 - 3 * t2 + 1) * kStripR[i] + (t3 - 2 * t2 + t) * h * kStripdR[i] +
                   (-2 * t3 + 3 * t2) * kStripR[i + 1] + (t3 - t2) * h * kStripdR[i + 1];
  return s * (R + 2.0 * x * std::log(4.0 / x));
}

double strip_influence_dH(double a) noexcept {
  const double x = std::abs(a);
  if (x == 0.0) return INFINITY;
  if (x >= kStripTableMax) {
    const double i2 = 1.0 / (x * x);
    return 0.5 * kPi / x - (kPi / 16.0) * i2 / x + (3.0 * kPi / 128.0) * i2 * i2 / x;
  }
  const double h = kStripTableMax / (kStripTableSize - 1);
  const int i = std::min(int(x / h), kStripTableSize - 2);
  const double t = (x - i * h) / h;
  const double t2 = t * t;
  const double dR = ((6 * t2 - 6 * t) * kStripR[i] + (-6 * t2 + 6 * t) * kStripR[i + 1]) / h +
                    (3 * t2 - 4 * t + 1) * kStripdR[i] + (3 * t2 - 2 * t) * kStripdR[i + 1];
  return dR + 2.0 * std::log(4.0 / x) - 2.0;
}

// ---------------------------------------------------------------------------------------------
double depth_displacement(double x1, double x2, double z, double E, double nu) noexcept {
  auto r = [z](double x) { return x / std::sqrt(x * x + z * z); };
  return (2.0 * (std::asinh(x2 / z) - std::asinh(x1 / z)) + (r(x2) - r(x1)) / (1.0 - nu)) / (kPi * E);
}

LineContactModel::LineContactModel(int n, double l, const std::vector<double>& R, double E,
                                   SliceMethod method, ApproachReference reference)
    : n_(n), l_(l), w_(0.0), E_(E), R_(R), method_(method), reference_(reference), k_slice_(0.0),
      depth_m_(INFINITY) {
  if (n < 1 || n > 400) {
    throw std::invalid_argument("LineContactModel.slices = " + std::to_string(n) + ": expected 1..400");
  }
  detail::require_positive("LineContactModel", "length_m", l);
  detail::require_positive("LineContactModel", "E_reduced_Pa", E);
  if (int(R.size()) != n) {
    throw std::invalid_argument("LineContactModel.reduced_radius_m: " + std::to_string(R.size()) +
                                " values: expected one per slice (" + std::to_string(n) + ")");
  }
  for (double r : R) detail::require_positive("LineContactModel", "reduced_radius_m", r);
  w_ = l / n;
  k_slice_ = palmgren_stiffness(l) / n;
  far_log_.assign(n, 0.0);
  far_p2_.assign(n, 0.0);
  far_p4_.assign(n, 0.0);
  for (int k = 1; k < n; ++k) {
    const double x1 = (k - 0.5) * w_, x2 = (k + 0.5) * w_;
    far_log_[k] = std::log(x2 / x1);
    far_p2_[k] = 1.0 / (x2 * x2) - 1.0 / (x1 * x1);
    far_p4_[k] = 1.0 / (x2 * x2 * x2 * x2) - 1.0 / (x1 * x1 * x1 * x1);
  }
  depth_.assign(n, 0.0);
  if (method == SliceMethod::AlternativeSlicing && reference == ApproachReference::Palmgren) {
    set_reference_depth(calibrate_reference_depth());
  }
}

void LineContactModel::set_reference_depth(double z) {
  if (!(z > 0.0)) detail::fail("LineContactModel", "reference_depth_m", z, "a value > 0 (infinity: half-space)");
  depth_m_ = z;
  if (std::isinf(z)) {
    std::fill(depth_.begin(), depth_.end(), 0.0);
    return;
  }
  depth_[0] = depth_displacement(-0.5 * w_, 0.5 * w_, z, E_);
  for (int k = 1; k < n_; ++k) depth_[k] = depth_displacement((k - 0.5) * w_, (k + 0.5) * w_, z, E_);
}

double LineContactModel::calibrate_reference_depth() const {
  // A flat line of this length and the mean reduced radius, 80 slices, at the calibration line
  // load: find z with approach(z) = Palmgren's approach. approach falls monotonically with 1/z
  // (the subtracted depth term grows), so a bracket on s = 1/z and Illinois steps suffice.
  constexpr int kSlices = 80;
  double Rm = 0.0;
  for (double r : R_) Rm += r / n_;
  LineContactModel cal(kSlices, l_, std::vector<double>(kSlices, Rm), E_, SliceMethod::AlternativeSlicing,
                       ApproachReference::HalfSpace);
  LineContactData d(cal);
  const double Q = kReferenceLineLoad_N_m * l_;
  const double target = palmgren_approach_m(Q, l_);
  // Displacement-controlled: at Palmgren's approach the line carries less than Q while the model
  // is softer than Palmgren's (s = 1/z too small: too little of the far field subtracted) and more
  // once it is stiffer, so f(s) = Q - force(s) changes sign where approach(Q; s) = Palmgren's
  // approach. One line-contact solve per s (a load-controlled solve nested a root in the
  // approach in every step: 8 ms of the bearing model's construction, now 2 ms).
  const std::vector<double> e_target(kSlices, target);
  auto excess = [&](double s) {
    cal.set_reference_depth(s > 0.0 ? 1.0 / s : INFINITY);
    if (solve_line_contact(cal, d, e_target.data()) != 0) {
      throw std::runtime_error("LineContactModel: the reference-depth calibration did not converge (length_m = " +
                               std::to_string(l_) + ")");
    }
    return Q - d.force_N;
  };
  double lo = 0.0, flo = excess(lo);
  if (flo <= 0.0) return INFINITY;  // the half-space is already as stiff as Palmgren
  // the depth term of a depth equal to the line length already removes most of the far field
  double hi = 1.0 / l_, fhi = excess(hi);
  for (int k = 0; k < 20 && fhi > 0.0; ++k) {
    lo = hi, flo = fhi;
    hi *= 2.0;
    fhi = excess(hi);
  }
  if (fhi > 0.0) throw std::runtime_error("LineContactModel: no reference depth reaches Palmgren's approach");
  double s = hi;
  if (!illinois(excess, lo, flo, hi, fhi, 1e-9 * Q, 1e-12 * hi, s)) {
    throw std::runtime_error("LineContactModel: the reference-depth calibration did not converge (length_m = " +
                             std::to_string(l_) + ")");
  }
  return 1.0 / s;
}

void LineContactModel::influence_column(double b, double* v, double* t) const noexcept {
  // C(k) = 4 / (pi^2 E') [H((k + 1/2) w / b) - H((k - 1/2) w / b)], H odd; beyond |a| = 6 the
  // asymptote of H makes the difference (pi/2) ln(x2/x1) + (pi/32) b^2 (1/x2^2 - 1/x1^2)
  // - (3 pi/512) b^4 (1/x2^4 - 1/x1^4), whose logarithm does not depend on b.
  // Newton term: b ~ sqrt(q), so q dC/dq = (b/2) dC/db = -(c/2) [G(a2) - G(a1)], G(a) = a H'(a).
  // t may be null: values only (the chord steps need no derivative).
  const double c = 4.0 / (kPi * kPi * E_);
  auto G = [](double a) { return a * strip_influence_dH(a); };
  double a_lo = 0.5 * w_ / b;
  double h_lo = strip_influence_H(a_lo), g_lo = t ? G(a_lo) : 0.0;
  const double* dz = depth_.data();
  v[0] = c * 2.0 * h_lo - dz[0];
  if (t) t[0] = -c * g_lo;
  const double b2 = b * b, b4 = b2 * b2;
  int k = 1;
  for (; k < n_ && (k - 0.5) * w_ < 6.0 * b; ++k) {  // near field: the tabulated strip function
    const double a_hi = (k + 0.5) * w_ / b;
    const double h_hi = strip_influence_H(a_hi);
    v[k] = c * (h_hi - h_lo) - dz[k];
    h_lo = h_hi;
    if (t) {
      const double g_hi = G(a_hi);
      t[k] = -0.5 * c * (g_hi - g_lo);
      g_lo = g_hi;
    }
  }
  // far field: the asymptote, b-independent logarithm precomputed (a branch-free loop)
  const double c0 = 0.5 * kPi * c, c2 = (kPi / 32.0) * c * b2, c4 = (3.0 * kPi / 512.0) * c * b4;
  const double* fl = far_log_.data();
  const double* f2 = far_p2_.data();
  const double* f4 = far_p4_.data();
  for (int kk = k; kk < n_; ++kk) v[kk] = c0 * fl[kk] + c2 * f2[kk] - c4 * f4[kk] - dz[kk];
  if (t) {
    const double d2 = -0.5 * (-2.0 * c2), d4 = -0.5 * (4.0 * c4);
    for (int kk = k; kk < n_; ++kk) t[kk] = d2 * f2[kk] + d4 * f4[kk];
  }
}

LineContactData::LineContactData(const LineContactModel& m)
    : line_load_N_m(m.slices(), 0.0),
      half_width_m(m.slices(), 0.0),
      max_pressure_Pa(m.slices(), 0.0),
      C_(m.slices(), m.slices()),
      J_(m.slices(), m.slices()),
      rhs_(m.slices()),
      sol_(m.slices()),
      lu_(m.slices()),
      q_old_(m.slices()),
      col_(m.slices()),
      tcol_(m.slices()),
      e_(m.slices()),
      active_(m.slices()) {}

namespace {

double hertz_half_width(double q, double R, double E) noexcept {
  return std::sqrt(8.0 * std::max(q, 1.0) * R / (kPi * E));  // floor: 1 N/m for unloaded slices
}

}  // namespace

int solve_line_contact(const LineContactModel& m, LineContactData& d, const double* e,
                       const LineContactSettings& s) noexcept {
  const int n = m.slices();
  const double w = m.width_m(), E = m.E_reduced_Pa();
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(e[i])) return -1;
  double* q = d.line_load_N_m.data();
  int status = 0;
  d.iterations = 0;
  // line load of an independent slice (its share of Palmgren's stiffness)
  auto independent = [&](double ei) { return ei > 0.0 ? m.slice_stiffness() * std::pow(ei, 10.0 / 9.0) / w : 0.0; };

  if (m.method() == SliceMethod::Independent) {
    for (int i = 0; i < n; ++i) q[i] = independent(e[i]);
  } else {
    // AST: C_ij = C(|i - j|; b_j) (LineContactModel::influence_column). b_j depends on q_j, so
    // Newton steps on C(q) q = e: J = C + T with T_ij = q_j dC_ij/dq_j, J q = e + T q_old, each
    // solved as a complementarity problem by an active set (inactive rows and columns replaced
    // by the identity, so the factorised matrix keeps its size and nothing is allocated).
    double emax = 0.0;
    for (int i = 0; i < n; ++i) emax = std::max(emax, e[i]);
    if (!(emax > 0.0)) {
      std::fill(q, q + n, 0.0);
      d.has_active_ = false;
      d.lu_valid_ = false;
    } else {
      int* act = d.active_.data();
      if (!d.has_active_) {
        for (int i = 0; i < n; ++i) {
          act[i] = e[i] > 0.0;
          // cold start from the independent-slice (Palmgren) loads
          q[i] = independent(e[i]);
        }
        d.has_active_ = true;
      }
      // Chord steps with the factorisation of the previous solve (same active set): the state
      // of a time step or sweep point differs little from the last one, so
      // q <- q - J_old^-1 (C(q) q - e) converges in a few steps at the cost of the influence
      // values alone; anything else (a sign change, a new contact, slow progress) falls back to
      // the Newton iteration below from the unchanged start.
      status = 1;
      bool chord_done = false;
      if (d.lu_valid_) {
        std::copy(q, q + n, d.q_old_.begin());
        double dq_prev = 0.0;
        for (int it = 0; it < 4; ++it) {
          ++d.iterations;
          // displacements u = C(q) q, column by column (C is Toeplitz in |i - j| per column)
          double* u = d.tcol_.data();  // free in the chord steps (d.e_ may hold e itself)
          std::fill(u, u + n, 0.0);
          for (int j = 0; j < n; ++j) {
            if (!act[j]) continue;
            const double* col = d.col_.data();
            m.influence_column(hertz_half_width(q[j], m.reduced_radius_m(j), E), d.col_.data(), nullptr);
            const double qj = q[j];
            for (int i = 0; i < j; ++i) u[i] += col[j - i] * qj;
            for (int i = j; i < n; ++i) u[i] += col[i - j] * qj;
          }
          double qmax = 0.0;
          for (int i = 0; i < n; ++i) {
            d.sol_[i] = act[i] ? u[i] - e[i] : 0.0;
            qmax = std::max(qmax, q[i]);
          }
          d.sol_ = d.lu_.solve(d.sol_);
          double dq = 0.0;
          bool sign_ok = true;
          for (int i = 0; i < n; ++i) {
            if (!act[i]) continue;
            q[i] -= d.sol_[i];
            dq = std::max(dq, std::abs(d.sol_[i]));
            if (!(q[i] >= 0.0)) sign_ok = false;
          }
          if (!sign_ok) break;
          // linear convergence: the next correction is about dq * (dq / dq_prev)
          const double next = dq_prev > 0.0 ? dq * dq / dq_prev : dq;
          dq_prev = dq;
          if (dq_prev > 0.0 && next > dq) break;  // not contracting: Newton instead
          if (next <= s.tolerance * qmax) {
            // complementarity of the inactive slices with the converged loads
            // (u of the loads before this last, negligible correction)
            bool gaps_ok = true;
            for (int i = 0; i < n && gaps_ok; ++i) {
              if (act[i]) continue;
              if (u[i] < e[i] - 1e-12 * emax) gaps_ok = false;
            }
            chord_done = gaps_ok;
            break;
          }
        }
        if (chord_done) {
          status = 0;
        } else {
          std::copy(d.q_old_.begin(), d.q_old_.end(), q);
        }
      }
      if (!chord_done) d.lu_valid_ = false;  // the Newton passes below refactorise
      for (int outer = 0; outer < s.max_outer && !chord_done; ++outer) {
        ++d.iterations;
        for (int j = 0; j < n; ++j) {
          m.influence_column(hertz_half_width(q[j], m.reduced_radius_m(j), E), d.col_.data(), d.tcol_.data());
          for (int i = 0; i < n; ++i) {
            const int k = i > j ? i - j : j - i;
            d.C_(i, j) = d.col_[k];
            d.J_(i, j) = d.col_[k] + d.tcol_[k];
          }
        }
        std::copy(q, q + n, d.q_old_.begin());
        // right-hand side e + T q_old
        for (int i = 0; i < n; ++i) {
          double r = e[i];
          for (int j = 0; j < n; ++j) r += (d.J_(i, j) - d.C_(i, j)) * d.q_old_[j];
          d.rhs_[i] = r;
        }
        bool ok = false, set_changed = false;
        for (int pass = 0; pass < 3 * n + 3; ++pass) {
          // reduced system in full size: identity rows/columns for the inactive slices
          for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) d.C_(i, j) = (act[i] && act[j]) ? d.J_(i, j) : (i == j ? 1.0 : 0.0);
            d.sol_[i] = act[i] ? d.rhs_[i] : 0.0;
          }
          d.lu_.compute(d.C_);
          d.sol_ = d.lu_.solve(d.sol_);
          bool negative = false;
          for (int i = 0; i < n; ++i) {
            q[i] = act[i] ? d.sol_[i] : 0.0;
            if (q[i] < 0.0) {
              act[i] = 0;
              negative = true;
              set_changed = true;
            }
          }
          if (negative) continue;
          bool entered = false;
          for (int i = 0; i < n; ++i) {
            if (act[i]) continue;
            double u = 0.0;
            for (int j = 0; j < n; ++j) u += d.J_(i, j) * q[j];
            if (u < d.rhs_[i] - 1e-12 * emax) {
              act[i] = 1;
              entered = true;
              set_changed = true;
            }
          }
          if (!entered) {
            ok = true;
            break;
          }
        }
        if (!ok) return 1;
        for (int i = 0; i < n; ++i) {
          if (!std::isfinite(q[i])) return -1;
        }
        double dq = 0.0, qmax = 0.0;
        for (int i = 0; i < n; ++i) {
          dq = std::max(dq, std::abs(q[i] - d.q_old_[i]));
          qmax = std::max(qmax, q[i]);
        }
        // Newton converges quadratically once the active set is settled: a step below
        // sqrt(tol) leaves an error of order tol, so the confirming step is skipped.
        if (dq <= s.tolerance * qmax || (outer > 0 && !set_changed && dq <= std::sqrt(s.tolerance) * qmax)) {
          status = 0;
          d.lu_valid_ = true;  // the factorisation of this active set serves the next chord steps
          break;
        }
      }
    }
  }
  d.force_N = 0.0;
  d.moment_Nm = 0.0;
  for (int i = 0; i < n; ++i) {
    const double b = q[i] > 0.0 ? std::sqrt(8.0 * q[i] * m.reduced_radius_m(i) / (kPi * E)) : 0.0;
    d.half_width_m[i] = b;
    d.max_pressure_Pa[i] = q[i] > 0.0 ? 2.0 * q[i] / (kPi * b) : 0.0;
    d.force_N += q[i] * w;
    d.moment_Nm += q[i] * w * m.position_m(i);
  }
  return status;
}

int solve_line_contact_load(const LineContactModel& m, LineContactData& d, const double* gap,
                            double force, double& approach, const LineContactSettings& s) noexcept {
  const int n = m.slices();
  if (!(force > 0.0) || !std::isfinite(force)) return -1;
  double gmin = gap[0];
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(gap[i])) return -1;
    gmin = std::min(gmin, gap[i]);
  }
  auto F = [&](double delta) -> double {
    for (int i = 0; i < n; ++i) d.e_[i] = delta - gap[i];
    if (solve_line_contact(m, d, d.e_.data(), s) < 0) return NAN;
    return d.force_N - force;
  };
  // bracket: the Palmgren approach of the whole line is a good scale
  const double scale = palmgren_approach_m(force, m.length_m());
  double lo = gmin, flo = -force;
  double hi = gmin + scale, fhi = F(hi);
  for (int k = 0; k < 60 && fhi < 0.0; ++k) {
    lo = hi, flo = fhi;
    hi = gmin + (hi - gmin) * 2.0;
    fhi = F(hi);
  }
  if (!(fhi >= 0.0)) return 1;
  double x = lo;
  if (!illinois(F, lo, flo, hi, fhi, 1e-10 * force, 1e-15, x)) return 1;
  approach = x;
  return 0;
}

}  // namespace kegel
