// Slice models of the roller/raceway line contact (seed paper Section 2.1.1).
//
// * RollerProfile: logarithmic crowning in the parameters a_p, c_p, d_p, k_p of the seed paper
//   (Teutsch; the form of ISO/TS 16281 / DIN 26281) plus the edge radius r_e.
// * LineContactModel / LineContactData / solve_line_contact(): the load of every slice for
//   given interferences (displacement control), with two fidelity levels:
//   - Independent: conventional slices, each with Palmgren's line-contact stiffness
//     (delta = 3.84e-5 Q^0.9 / l^0.8, N and mm) shared in proportion to its width;
//   - AlternativeSlicing: slices coupled through the elastic half-space, in the manner of
//     Teutsch and Sauer (ASME J. Tribol. 126 (2004) 436-442): the displacement of slice i is the
//     sum over all slices j of the Boussinesq displacement of a band of width w and semi-elliptic
//     (Hertzian) cross-section of half-width b_j(q_j); neighbours load each other, so edge
//     pressure under tilt and at the ends of an unprofiled roller is represented.
//
// Reference of the AST approach (ApproachReference). The half-space displacement is measured
// against a point at infinite depth; for a line contact it grows with ln(l / b) without bound
// (the 2D half-space has no finite approach at all), while a roller and a ring are finite
// bodies. In the spirit of the finite-size adjustments of half-space contact models (de Mul,
// Kalker and Vree, "An orthogonal uniform/parabolic surface pressure half-space element for
// the analysis of non-Hertzian contact", Computational Mechanics, CIMNE 1998; their earlier
// ASME J. Tribol. 108 (1986) 140-148 with Fredriksson is cited for it but was not checked
// here), the approach is measured against points at a reference depth z
// below each surface: the Boussinesq displacement at depth z under slice i (both bodies) is
// subtracted from the surface displacement. kegel does not know the depth of a roller/ring pair
// from first principles (for l = 20 mm, R' = 7.25 mm a depth of 8.5 mm, the 32216 roller's
// radius, gives -21 % against Palmgren, 20 mm -8 %, infinity +7 %), so with
// ApproachReference::Palmgren z is set once per contact such
// that a flat (unprofiled) roller of the line's length carries Palmgren's approach at the
// calibration line load of 1000 N/mm, the middle of Palmgren's range 200 ... 2000 N/mm (in a
// discretisation of 80 slices, so z does not depend on the slice count). Both fidelity levels
// then share Palmgren's load-deflection level (the stiffness basis of ISO/TS 16281), and the
// AST adds the distribution: edge peaks, tilt, profile. ApproachReference::HalfSpace keeps the
// infinite depth (the pure half-space, as the cell model). When the half-space approach is
// already below Palmgren's (short rollers of large reduced radius: l = 8 mm with R' = 7.25 mm
// is -4 %, with R' = 20 mm -16 % at 1000 N/mm) no depth can raise it and z stays infinite.
// Cost: one calibration per model, 1.5 ... 8 ms.
//
// Interference e_i > 0 means the undeformed surfaces overlap at slice i by e_i.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace kegel {

/// Roller profile drop (material removed from the nominal cone) along the roller axis.
///
/// kegel's reading of the paper's parameters (ISO/TS 16281 form, Teutsch's names):
///   u(x) = (2|x| - d_p) / c_p  for |x| > d_p / 2 (d_p: length of the straight middle part),
///   drop = a_p D_w ln(1 / (1 - u^2))  (a_p D_w: profile scale; ISO/TS 16281 uses
///                                      0.00035 D_w or 0.0005 D_w),
///   continued linearly with its slope over the last k_p before the log's pole at
///   |x| = (d_p + c_p)/2, and, beyond the straight generator (|x| > L/2 - r_e), rounded by the
///   edge radius r_e. Throws std::invalid_argument on invalid values.
class RollerProfile {
 public:
  struct Values {
    double roller_diameter_m = 0.0;  ///< D_w
    double length_m = 0.0;           ///< L
    double a_p = 0.0;                ///< profile scale (0: unprofiled)
    double c_p_m = 0.0;              ///< length of the logarithmic zone
    double d_p_m = 0.0;              ///< straight middle length
    double k_p_m = 0.0;              ///< linear end zone before the log's pole
    double edge_radius_m = 0.0;      ///< r_e
  };
  explicit RollerProfile(const Values& v);
  const Values& values() const noexcept { return v_; }
  /// Drop at axial position x from the roller mid-length (>= 0, metres).
  double drop_m(double x_m) const noexcept;

 private:
  double log_drop(double ax) const noexcept;
  Values v_;
  double x_lin_ = 0.0, drop_lin_ = 0.0, slope_lin_ = 0.0;  // start, value and slope of the linear zone
};

/// Palmgren's roller/raceway approach delta = 3.84e-5 Q^0.9 / l^0.8 (N, mm), in SI [m].
double palmgren_approach_m(double load_N, double length_m) noexcept;
/// Its inverse as a stiffness: Q = palmgren_stiffness(l) delta^(10/9) [N / m^(10/9)].
double palmgren_stiffness(double length_m) noexcept;

/// Strip influence function H(a) = int_{-1}^{1} sqrt(1 - t^2) asinh(a / |t|) dt (odd in a);
/// tabulated (mbs_core/tools/gen_strip_table.py) below a = 6, asymptotic above.
double strip_influence_H(double a) noexcept;
/// dH/da (even in a).
double strip_influence_dH(double a) noexcept;

enum class SliceMethod { Independent = 0, AlternativeSlicing = 1 };

/// What the AST approach is measured against (see the file comment).
enum class ApproachReference { Palmgren = 0, HalfSpace = 1 };

/// Line load at which ApproachReference::Palmgren sets the reference depth [N/m].
inline constexpr double kReferenceLineLoad_N_m = 1.0e6;
/// Poisson's ratio of both bodies in the depth term of the Boussinesq solution (steel).
inline constexpr double kReferencePoisson = 0.3;

/// Boussinesq displacement at depth z below the middle of a slice, caused by a unit line load
/// on the surface between x1 and x2 along the line (relative to the slice), both bodies with
/// the pair modulus E' (identical materials, Poisson's ratio nu) [m / (N/m)]:
/// (1 / (pi E')) [2 (asinh(x2/z) - asinh(x1/z)) + (x2/r2 - x1/r1) / (1 - nu)], r = sqrt(x^2 + z^2).
double depth_displacement(double x1_m, double x2_m, double depth_m, double E_reduced_Pa,
                          double poisson = kReferencePoisson) noexcept;

/// The fixed description of a line contact: slice positions and widths, reduced radii, method.
class LineContactModel {
 public:
  /// @param slices             number of slices n (1..400)
  /// @param length_m           length of the contact line that is sliced (effective length l)
  /// @param reduced_radius_m   R' of each slice (n values, rolling direction)
  /// @param E_reduced_Pa       E'
  /// @param method             Independent or AlternativeSlicing
  /// @param reference          what the AST approach is measured against (ignored by Independent)
  LineContactModel(int slices, double length_m, const std::vector<double>& reduced_radius_m,
                   double E_reduced_Pa, SliceMethod method,
                   ApproachReference reference = ApproachReference::Palmgren);
  int slices() const noexcept { return n_; }
  double length_m() const noexcept { return l_; }
  double width_m() const noexcept { return w_; }
  /// Position of slice i along the line, from its middle.
  double position_m(int i) const noexcept { return (i + 0.5) * w_ - 0.5 * l_; }
  double reduced_radius_m(int i) const noexcept { return R_[i]; }
  double E_reduced_Pa() const noexcept { return E_; }
  SliceMethod method() const noexcept { return method_; }
  ApproachReference reference() const noexcept { return reference_; }
  /// Depth of the approach's reference points below the surfaces [m] (infinity: half-space).
  double reference_depth_m() const noexcept { return depth_m_; }
  /// Measure the AST approach against points at this depth (infinity: the half-space).
  /// Throws std::invalid_argument unless depth > 0.
  void set_reference_depth(double depth_m);
  /// Palmgren stiffness of one slice: Q_i = k e_i^(10/9) [N / m^(10/9)] (Independent).
  double slice_stiffness() const noexcept { return k_slice_; }
  /// Column of the AST influence matrix for a slice of half-width b: v[k] is the displacement
  /// of a slice k slices away per unit line load [m / (N/m)], k = 0 .. n-1, relative to the
  /// reference depth. Far from the band (|x|/b >= 6) the b-independent logarithm is precomputed,
  /// as is the (b-independent) depth term.
  /// t[k] = q dC(k)/dq for the same column (Newton term; C depends on q through b ~ sqrt(q));
  /// t may be null when only the values are wanted.
  void influence_column(double b, double* v, double* t) const noexcept;

 private:
  double calibrate_reference_depth() const;
  int n_;
  double l_, w_, E_;
  std::vector<double> R_;
  SliceMethod method_;
  ApproachReference reference_;
  double k_slice_;
  double depth_m_;
  std::vector<double> far_log_, far_p2_, far_p4_;  // per slice distance k >= 1
  std::vector<double> depth_;                      // depth term per slice distance k >= 0 (0: half-space)
};

/// Settings of the solver.
struct LineContactSettings {
  double tolerance = 1e-10;  ///< relative change of the line loads between Newton steps (AST)
  int max_outer = 30;        ///< Newton steps on the Hertz half-widths b(q) (AST)
};

/// State and workspace of a line contact (warm start: the previous line loads).
class LineContactData {
 public:
  explicit LineContactData(const LineContactModel& model);
  std::vector<double> line_load_N_m;   ///< q_i
  std::vector<double> half_width_m;    ///< Hertz half-width b_i of each loaded slice
  std::vector<double> max_pressure_Pa; ///< p0_i = 2 q_i / (pi b_i)
  double force_N = 0.0;                ///< sum q_i w
  double moment_Nm = 0.0;              ///< sum q_i w x_i (about the middle of the line)
  int iterations = 0;

 private:
  friend int solve_line_contact(const LineContactModel&, LineContactData&, const double*,
                                const LineContactSettings&) noexcept;
  friend int solve_line_contact_load(const LineContactModel&, LineContactData&, const double*,
                                     double, double&, const LineContactSettings&) noexcept;
  Eigen::MatrixXd C_, J_;
  Eigen::VectorXd rhs_, sol_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  std::vector<double> q_old_, col_, tcol_, e_;
  std::vector<int> active_;
  bool has_active_ = false;
  bool lu_valid_ = false;  // lu_ factorises the Newton matrix of the current active set
};

/// Line loads for given interferences e_i (n values): displacement control.
/// @return 0 converged, 1 not converged within the limits (last iterate kept), -1 bad input.
int solve_line_contact(const LineContactModel& model, LineContactData& data,
                       const double* interference_m, const LineContactSettings& settings = {}) noexcept;

/// Load control helper: find the approach delta0 such that the slices with interference
/// e_i = delta0 - gap_i carry the total force (bracketing + Illinois iteration).
/// @return 0 on success, non-zero otherwise; approach_m receives delta0.
int solve_line_contact_load(const LineContactModel& model, LineContactData& data,
                            const double* gap_m, double force_N, double& approach_m,
                            const LineContactSettings& settings = {}) noexcept;

}  // namespace kegel
