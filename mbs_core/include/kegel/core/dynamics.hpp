// Dynamic multibody simulation of a tapered roller bearing (issue "Dynamic multibody
// simulation"): every roller and the cage as 6-DOF rigid bodies, the inner ring driven at a
// prescribed speed and free (or held) in translation and tilt, the outer ring fixed.
//
// Frame R (outer ring, inertial) as in quasi_static.hpp: z = bearing axis towards the rollers'
// large ends, x = direction of the radial load.
//
// State vector (SI), in this order:
//   roller j (12 values): p_RC (centre of mass), a_R (unit axis, small -> large end),
//                         v_RC, w_R (angular velocity, frame R);
//   cage (13 values):     p_RG (centre), q (unit quaternion w, x, y, z: cage axes in R),
//                         v_RG, w_G (angular velocity in the cage's own axes);
//   inner ring (10):      d (displacement of its pivot), v (its velocity), tilt (rx, ry) and
//                         tilt rates; the tilt turns the ring about its pivot on the axis in the
//                         roller mid-plane: x = c + d + Rx(rx) Ry(ry) (x_ring - c).
// A roller is a body of revolution: its spin angle does not enter any force, so its attitude is
// its axis alone and its Euler equation is written in frame R,
//   I w' = M - (I_a - I_t)(a . w)(w x a),   I = I_t 1 + (I_a - I_t) a a^T,
// which holds the gyroscopic moment. The cage (Z pockets) needs its full attitude: quaternion
// and Euler's equations in its own axes. Unit length of a and q is kept by a stabilising term
// -lambda (|a|^2 - 1) a (Baumgarte), lambda = kNormStabilisation_1_s.
//
// Contacts per roller (the same models as the quasi-static solution; seed paper Section 2.1):
// both raceways by slices (independent Palmgren slices or alternative slicing, Sec. 2.1.1)
// with parametric damping (Eq. 1-3) and the friction of every slice (evaluate_slice: Eq. 4-30,
// 36); the rib as one elliptic Hertz contact with its friction (evaluate_cell, Eq. 31-35); the
// cage window: the roller against the window's two edges (lines on the shell's inner face,
// cage_edge_height above the roller axis, following the roller's taper with the circumferential
// clearance) at cage_points points each, and against the end bars (planes at +-(L/2 + axial
// clearance/2) along the pocket), each point with its share of Palmgren's law, Eq. 1-3 damping and
// the Coulomb friction of Eq. 37; the cage touches nothing else. Rolling resistance
// (Eq. 16, 19, 20) acts through the shift of each slice's normal force towards the inlet, an
// action-reaction pair on roller and ring, as in the quasi-static solution.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "kegel/core/hertz.hpp"
#include "kegel/core/quasi_static.hpp"
#include "kegel/core/slice.hpp"

namespace kegel {

/// Position, attitude and velocity of one body, handed to force elements (frame R).
struct BodyKinematics {
  Eigen::Vector3d p_RC = Eigen::Vector3d::Zero();   ///< centre of mass
  Eigen::Vector3d axis_R = Eigen::Vector3d::UnitZ(); ///< symmetry axis (roller: small -> large end)
  Eigen::Vector3d v_RC = Eigen::Vector3d::Zero();   ///< velocity of the centre of mass
  Eigen::Vector3d w_R = Eigen::Vector3d::Zero();    ///< angular velocity
};

/// What a force element sees besides its body.
struct ForceContext {
  double time_s = 0.0;
  double inner_speed_rad_s = 0.0;
  double cage_speed_rad_s = 0.0;  ///< cage angular velocity about the bearing axis
};

/// A force and a moment about the body's centre of mass (frame R).
struct Wrench {
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();
  Eigen::Vector3d moment_Nm = Eigen::Vector3d::Zero();
};

/// An external force element acting on rollers and/or the cage: the API through which the
/// coupling layer (hydraulic drag and churning from correlations or CFD fits) acts on the bodies.
///
/// wrench() is called inside the integrator's right-hand side: it must not throw, must not
/// allocate, and must be a smooth function of the state (the Jacobian is taken by finite
/// differences). body = -1 for the cage, 0 .. Z-1 for roller j. Return 0 on success; a
/// positive value asks the integrator for a smaller step, a negative one stops the run (the
/// message() then says why).
class ForceElement {
 public:
  virtual ~ForceElement() = default;
  /// May wrench() run on several threads at once (for different bodies)?
  virtual bool thread_safe() const noexcept { return true; }
  virtual int wrench(int body, const BodyKinematics& k, const ForceContext& ctx, Wrench& out) const noexcept = 0;
  virtual std::string message() const { return {}; }
};

/// Hydraulic drag of the oil on rollers and cage in closed form (the form the coupling layer
/// fits to CFD results or takes from a correlation):
///   roller: F = -1/2 rho C_D A |u| u, u = velocity of the roller centre relative to oil that
///           swirls about the bearing axis at swirl_ratio x the cage speed; moment about its axis
///           -c_spin ((w - w_cage e_z) . a) a (viscous drag of its spin relative to the cage frame,
///           where the oil around the rollers turns: the frame of a frozen-rotor CFD run);
///   cage:   moment about the bearing axis -c_cage w_z - c_cage2 |w_z| w_z.
struct DragElementValues {
  double oil_density_kg_m3 = 0.0;
  double roller_drag_coefficient = 0.0;  ///< C_D
  double roller_frontal_area_m2 = 0.0;   ///< A (mean diameter x length)
  double swirl_ratio = 0.0;
  double roller_spin_drag_Nms = 0.0;     ///< c_spin
  double cage_drag_Nms = 0.0;            ///< c_cage
  double cage_drag_Nms2 = 0.0;           ///< c_cage2
};
class DragElement final : public ForceElement {
 public:
  explicit DragElement(const DragElementValues& v);  ///< throws std::invalid_argument
  int wrench(int body, const BodyKinematics& k, const ForceContext& ctx, Wrench& out) const noexcept override;
  const DragElementValues& values() const noexcept { return v_; }

 private:
  DragElementValues v_;
};

/// Inertia of the moving bodies and the cage geometry (SI).
struct DynamicValues {
  double roller_mass_kg = 0.0;
  double roller_inertia_axial_kgm2 = 0.0;
  double roller_inertia_transverse_kgm2 = 0.0;  ///< about the centre of mass
  double roller_com_offset_m = 0.0;              ///< centre of mass from the mid-point M, along the axis
  double cage_mass_kg = 0.0;
  double cage_inertia_axial_kgm2 = 0.0;
  double cage_inertia_transverse_kgm2 = 0.0;
  double cage_pitch_radius_m = 0.0;         ///< radius of the pocket centres
  double cage_pocket_clearance_m = 0.0;     ///< circumferential, total (both sides)
  double cage_pocket_axial_clearance_m = 0.0;
  double cage_edge_height_m = 0.0;          ///< window edges above the roller axis (towards the cup)
  double ring_mass_kg = 0.0;                ///< inner ring with the shaft share that moves with it
  double ring_inertia_axial_kgm2 = 0.0;     ///< for the gyroscopic moment of a tilting ring
  double ring_inertia_transverse_kgm2 = 0.0;  ///< about the pivot
  double damping_time_s = 0.0;              ///< d_max = damping_time x contact stiffness at delta_max (Eq. 2)
  Eigen::Vector3d gravity_m_s2 = Eigen::Vector3d::Zero();
  int cage_points = 4;                      ///< points per window edge
  bool cage = true;                         ///< false: no cage (rollers free)
};

/// The driven inner ring: a speed profile (piecewise linear in time, held constant after the
/// last point), loads on it, and which of its translations and tilts are free. A held tilt stays
/// at its initial value (the imposed misalignment of the quasi-static initial state).
struct RingDrive {
  std::vector<double> time_s{0.0};
  std::vector<double> speed_rad_s{0.0};
  double axial_N = 0.0;      ///< pushes the ring towards the apex (-z)
  double radial_N = 0.0;     ///< along +x, at the pivot
  /// Optional load history (piecewise linear, held after the last point): when load_time_s is
  /// not empty, axial_profile_N and radial_profile_N (one value per time) replace the constant loads.
  std::vector<double> load_time_s, axial_profile_N, radial_profile_N;
  double axial(double t) const noexcept;
  double radial(double t) const noexcept;
  double tilt_moment_x_Nm = 0.0, tilt_moment_y_Nm = 0.0;  ///< about the pivot (tilt_free)
  bool free_x = true, free_y = true, free_z = true;
  bool tilt_free = false;
  double speed(double t) const noexcept;
  double acceleration(double t) const noexcept;
};

/// The fixed description of a dynamic bearing model.
class DynamicModel {
 public:
  DynamicModel(std::shared_ptr<const BearingModel> bearing, const DynamicValues& values,
               const FrictionParameters& friction, const SurfacePair& raceway, const SurfacePair& rib,
               const ContactLubricantState& lubricant);  ///< throws std::invalid_argument
  /// With a lubricant state per ring (issue 27, item 6): the outer raceway's contacts use
  /// outer_lubricant, the inner raceway's and the rib's (the inner ring's) inner_lubricant.
  /// The constructor above passes one state for both.
  DynamicModel(std::shared_ptr<const BearingModel> bearing, const DynamicValues& values,
               const FrictionParameters& friction, const SurfacePair& raceway, const SurfacePair& rib,
               const ContactLubricantState& outer_lubricant,
               const ContactLubricantState& inner_lubricant);  ///< throws std::invalid_argument
  const BearingModel& bearing() const noexcept { return *bearing_; }
  const DynamicValues& values() const noexcept { return v_; }
  const FrictionParameters& slice_friction() const noexcept { return fp_slice_; }
  const FrictionParameters& rib_friction() const noexcept { return fp_rib_; }
  const SurfacePair& raceway() const noexcept { return race_; }
  const SurfacePair& rib() const noexcept { return rib_; }
  /// The lubricant state of the outer ring's contacts (its raceway).
  const ContactLubricantState& outer_lubricant() const noexcept { return lub_outer_; }
  /// The lubricant state of the inner ring's contacts (its raceway and the rib).
  const ContactLubricantState& inner_lubricant() const noexcept { return lub_inner_; }
  int roller_count() const noexcept { return bearing_->values().roller_count; }
  int state_size() const noexcept { return 12 * roller_count() + 23; }
  int cage_offset() const noexcept { return 12 * roller_count(); }
  int ring_offset() const noexcept { return 12 * roller_count() + 13; }
  double pocket_damping_Ns_m() const noexcept { return d_pocket_; }
  /// The rib's Hertz contact at interference delta (scaled from one evaluation: the rib's radii
  /// are fixed, so Q ~ delta^1.5 and the semi-axes ~ delta^0.5).
  HertzEllipse rib_contact(double delta_m) const noexcept;
  double rib_damping_Ns_m() const noexcept { return d_rib_; }
  /// Nominal pose of pocket k in the cage's axes: centre, circumferential and axis directions.
  void pocket_frame(int k, Eigen::Vector3d& centre, Eigen::Vector3d& e_x, Eigen::Vector3d& e_y,
                    Eigen::Vector3d& e_z) const noexcept;
  /// Half-width of window k's edges at station y along the pocket (from its centre).
  double window_half_width_m(double y_m) const noexcept;

 private:
  std::shared_ptr<const BearingModel> bearing_;
  DynamicValues v_;
  FrictionParameters fp_slice_, fp_rib_;
  SurfacePair race_, rib_;
  ContactLubricantState lub_outer_, lub_inner_;
  double d_pocket_ = 0.0, d_rib_ = 0.0;
  HertzEllipse rib_ref_;
};

/// Per-roller outputs of one evaluation.
struct RollerOutputs {
  double outer_N = 0.0, inner_N = 0.0, rib_N = 0.0, cage_N = 0.0;  ///< normal loads (elastic part)
  double spin_rad_s = 0.0;         ///< spin about its axis relative to the cage
  double sliding_outer_m_s = 0.0;  ///< rolling-direction sliding speed at the middle slice (roller - ring)
  double sliding_inner_m_s = 0.0;
  double skew_rad = 0.0;           ///< axis rotation about the contact normal (relative to nominal)
  double tilt_rad = 0.0;           ///< axis rotation about the circumferential direction
};

/// Outputs of one evaluation of the right-hand side (filled on request).
struct DynamicOutputs {
  enum Contact { kOuter = 0, kInner = 1, kRib = 2 };
  double time_s = 0.0;
  double inner_speed_rad_s = 0.0;
  double cage_speed_rad_s = 0.0;
  double drive_torque_Nm = 0.0;       ///< torque the rollers' contacts put on the inner ring, negated
  double outer_ring_torque_Nm = 0.0;  ///< moment of the roller forces on the outer ring about z
  double torque_by_contact_Nm[3] = {0, 0, 0};  ///< outer raceway (on the cup), inner raceway and rib (on the cone, negated)
  double power_W[3][5] = {};          ///< by contact and mechanism (BearingFriction's order)
  double Lambda_min[3] = {0, 0, 0};   ///< smallest film parameter (Eq. 30) of each contact's slices
  double phi_max[3] = {0, 0, 0};      ///< largest asperity load ratio (Eq. 29)
  double damping_power_W = 0.0;
  double cage_power_W = 0.0;          ///< friction in the cage windows (Eq. 37)
  double external_power_W = 0.0;      ///< power the force elements take from the bodies
  double power_input_W = 0.0;         ///< drive torque x inner-ring speed
  double kinetic_energy_J = 0.0;
  double max_penetration_m = 0.0;     ///< largest interference of any contact
  /// -sum F . (v_body - v_other) over every contact force at its point of action: the power the
  /// contacts take from the bodies (dissipation plus the rate of the elastic energy)
  double contact_work_W = 0.0;
  Eigen::Vector3d ring_force_N = Eigen::Vector3d::Zero();  ///< of the rollers on the inner ring
  Eigen::Vector3d ring_moment_Nm = Eigen::Vector3d::Zero();  ///< ... about its pivot
  std::vector<RollerOutputs> rollers;
};

/// What one roller's contacts contribute to the outputs of an evaluation (summed over the rollers
/// in roller order afterwards, so the result does not depend on the number of threads).
struct ContactAccumulators {
  double P[3][5] = {};
  double damping_W = 0.0, cage_W = 0.0, external_W = 0.0;
  double Lmin[3] = {1e300, 1e300, 1e300}, phimax[3] = {0, 0, 0};
  double contact_W = 0.0;  ///< work rate of all contact forces (dissipation + elastic energy rate)
  double torque[3] = {0, 0, 0};
  double max_pen = 0.0;
};

/// State and workspace of a dynamic simulation (per-roller line-contact data for warm starts,
/// buffers of the slice geometry per thread; nothing is allocated in the right-hand side).
/// threads > 1 evaluates the rollers in parallel (OpenMP) unless a force element is not thread
/// safe (a Python callable); results do not depend on the thread count.
class DynamicData {
 public:
  explicit DynamicData(const DynamicModel& model, int threads = 1);
  int threads = 1;
  std::vector<LineContactData> inner_lines, outer_lines;
  // per-roller contributions of the last evaluation: wrench on the roller (about its centre),
  // on the cage (about the cage centre), force on the inner ring
  std::vector<Wrench> on_roller, on_cage;
  std::vector<Wrench> on_ring;                ///< about the ring's pivot
  std::vector<Wrench> base_cage;              ///< the same at the Jacobian's base state
  std::vector<Wrench> base_ring;
  /// One part of a roller's contacts: its wrench on the roller and on the other body (part 0:
  /// outer raceway, no other body; 1: inner raceway and rib, on the inner ring; 2: cage window,
  /// gravity and force elements, on the cage). parts[3 j + k] from the last evaluation,
  /// base_parts at the Jacobian's base state (a column that moves only the cage or the inner
  /// ring re-evaluates only the part it changes).
  struct PartWrench {
    Wrench roller, other;
  };
  std::vector<PartWrench> parts, base_parts;
  /// The state of the last complete evaluation of the right-hand side (valid: nothing has
  /// overwritten its per-roller contributions since): the Jacobian at that state reuses them.
  std::vector<double> last_y;
  double last_t = 0.0;
  bool last_valid = false;
  std::vector<std::vector<SliceGeometry>> geo;  ///< per thread
  std::vector<std::vector<double>> e;            ///< per thread
  std::vector<double> xi;
  std::vector<ContactAccumulators> acc;          ///< per roller
  std::vector<int> status;                       ///< per roller
  std::vector<const ForceElement*> elements;  ///< not owned
  std::string element_message;                ///< why a force element failed
};

/// Evaluate the state derivative ydot = f(t, y). out may be null (the hot path).
/// only_roller >= 0 evaluates that roller's contributions only (workspace on_roller etc.),
/// without assembling ydot (used by the coloured Jacobian).
/// @return 0 success; 1 recoverable (an interference beyond any physical value: the step was too
///         large); -1 a force element failed or the state is not finite.
int dynamic_rhs(const DynamicModel& model, DynamicData& data, const RingDrive& drive, double t, const double* y,
                double* ydot, DynamicOutputs* out = nullptr) noexcept;

/// Jacobian df/dy by coloured finite differences: every roller's column c is perturbed at once
/// (rollers do not touch each other; their effect on cage and ring is kept apart through the
/// per-roller contributions), the cage's and ring's columns one by one: 12 + 13 + 10
/// evaluations instead of 12 Z + 23. A cage column re-evaluates only the cage windows, a ring
/// column only the inner raceways and ribs (the rest from the base state); the columns of a held
/// ring translation or tilt are zero. The base state's evaluation is the last one when that was
/// at (t, y). J is column-major with leading dimension ld (>= N; rows and columns past N are
/// zero). f0 = f(t, y).
int dynamic_jacobian(const DynamicModel& model, DynamicData& data, const RingDrive& drive, double t, const double* y,
                     const double* f0, double* J, double* work, int ld = 0) noexcept;

/// A state from the quasi-static solution: rollers at their solved places, turning with the
/// cage at cage_speed with spins roller_spin (relative to the cage), the ring displaced by ring.
std::vector<double> initial_state(const DynamicModel& model, const BearingData& qs, double cage_speed_rad_s,
                                  const std::vector<double>& roller_spin_rad_s);

/// The integrator: CVODE (BDF, Newton, dense direct solver with the coloured Jacobian).
struct IntegratorSettings {
  double rtol = 1e-5;
  double atol_position_m = 1e-9;     ///< positions and ring displacement
  double atol_axis = 1e-7;           ///< axis / quaternion components
  double atol_velocity_m_s = 1e-5;
  double atol_rate_rad_s = 1e-3;
  double max_step_s = 0.0;           ///< 0: no limit
  long max_steps = 200000;           ///< per advance() call
  bool coloured_jacobian = true;     ///< false: CVODE's own difference quotients (every column)
  /// With the coloured Jacobian: LU of the Newton matrix in block-arrow form (each roller's block
  /// coupled only to the cage and the inner ring, about 20 times fewer operations than a dense
  /// LU for 16 rollers); false: SUNDIALS' dense LU (the same solution to rounding).
  bool structured_linear_solver = true;
  /// The quadratures (kQuadratureCount) as states of the ODE, outside its error test, their
  /// integrands summed in every evaluation of the right-hand side: no extra evaluation per step
  /// (CVODES' quadratures evaluate the contacts once more at every step's corrected state).
  /// false: CVODES' quadratures. The two integrals differ by the Newton iteration's tolerance.
  bool quadratures_in_state = true;
  long jacobian_max_age_steps = 0;   ///< steps between Jacobian evaluations at most (0: CVODE's 51)
  /// Velocities and rates under absolute tolerances only (atol_velocity_m_s, atol_rate_rad_s):
  /// the friction follows the sliding speed, whose error a relative tolerance on the orbital
  /// speed would not bound.
  bool absolute_velocity_tolerance = true;
  int threads = 1;                   ///< rollers evaluated in parallel (OpenMP)
};

/// Quadratures (time integrals along the solution) the simulation keeps, in this order:
/// outer-ring torque, drive torque, input power, power[contact][mechanism] (15), damping power,
/// cage power, external power, cage speed, torque by contact (3), contact work rate. Their differences over an
/// interval divided by its length are the exact means of the solution (sampling a stiff contact
/// force at interpolated output times is not: its traction reacts to 1e-5 m/s).
constexpr int kQuadratureCount = 26;
void quadrature_values(const DynamicOutputs& out, double* q) noexcept;

class DynamicSimulation {
 public:
  DynamicSimulation(std::shared_ptr<const DynamicModel> model, const RingDrive& drive, const IntegratorSettings& s,
                    double t0, const std::vector<double>& y0);  ///< throws std::invalid_argument
  ~DynamicSimulation();
  DynamicSimulation(const DynamicSimulation&) = delete;
  DynamicSimulation& operator=(const DynamicSimulation&) = delete;
  /// Integrate to t_end. @return 0 success, < 0 the CVODE flag; message() says why.
  int advance(double t_end) noexcept;
  double time() const noexcept { return t_; }
  std::vector<double> state() const;
  /// The quadratures at the current time (see kQuadratureCount), from t0 (plus q0 on a resume).
  std::vector<double> quadratures() const;
  void set_quadrature_offset(const std::vector<double>& q0) { q0_ = q0; q0_.resize(kQuadratureCount, 0.0); }
  /// Evaluate the outputs at the current state.
  DynamicOutputs outputs();
  const std::string& message() const noexcept { return msg_; }
  void add_element(std::shared_ptr<const ForceElement> e);
  long steps() const;
  long rhs_evaluations() const;
  long jacobian_evaluations() const;
  double last_step_s() const;
  const DynamicModel& model() const noexcept { return *model_; }
  DynamicData& data() noexcept { return data_; }
  RingDrive& drive() noexcept { return drive_; }

  // for the no-throw callbacks
  struct Impl;

 private:
  void release() noexcept;
  std::shared_ptr<const DynamicModel> model_;
  DynamicData data_;
  RingDrive drive_;
  IntegratorSettings settings_;
  std::vector<std::shared_ptr<const ForceElement>> owned_;
  double t_ = 0.0;
  std::vector<double> q0_ = std::vector<double>(kQuadratureCount, 0.0);
  std::string msg_;
  Impl* impl_ = nullptr;
};

}  // namespace kegel
