// Quasi-static load distribution of a tapered roller bearing (issue "Quasi-static bearing
// solution", first part): the inner ring's equilibrium under axial load, radial load and tilt
// moment against the fixed outer ring, through every roller's raceway slices and rib contact.
//
// Frame R (outer ring, inertial): z = bearing axis, pointing from the rollers' small ends to
// their large ends (away from the common apex); x = direction of the radial load (the load zone
// is centred at azimuth 0). Roller j sits at azimuth psi_j = 2 pi j / Z.
//
// Unknowns: the inner ring's displacement (dx, dy, dz) and tilt (rx, ry) - 5 DOF - and, per
// roller, its in-plane displacement (radial u, axial w) and tilt t about its circumferential
// axis - 3 DOF. Each roller's equilibrium is solved for the current ring pose (Newton, 3 x 3),
// which condenses the problem to the ring's 5 equations (Newton with a finite-difference
// Jacobian). Contact forces: the slice models (independent or AST) for both raceways and the
// closed-form elliptic Hertz contact for the rib; friction is not part of the load
// distribution. Centrifugal force m omega_c^2 r acts on each roller. A roller out of contact is
// held at its place by a weak spring (1 N/m, 1e-3 N m/rad: a stand-in for the cage; its force
// is below 1e-4 N at the displacements of loaded rollers, 1e-8 of their loads).
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "kegel/core/cell_contact.hpp"
#include "kegel/core/contact_geometry.hpp"
#include "kegel/core/hertz.hpp"
#include "kegel/core/line_contact.hpp"
#include "kegel/core/slice.hpp"

namespace kegel {

/// The fixed description of a bearing for the quasi-static solution (SI, frame R).
struct BearingModelValues {
  int roller_count = 0;
  double pitch_radius_m = 0.0;        ///< distance of the roller mid-point from the axis
  double roller_mid_z_m = 0.0;        ///< axial position of the roller mid-point
  double roller_axis_angle_rad = 0.0; ///< beta
  double apex_z_m = 0.0;              ///< common apex of the raceway cones
  double cup_angle_rad = 0.0;         ///< alpha_o
  double cone_angle_rad = 0.0;        ///< alpha_i
  double roller_mean_radius_m = 0.0;
  double roller_half_angle_rad = 0.0; ///< gamma
  double roller_length_m = 0.0;
  double roller_mass_kg = 0.0;
  double cage_pocket_clearance_m = 0.0;  ///< circumferential, total (both sides); CageModel::Walls
  RollerProfile::Values profile;
  double E_reduced_Pa = 0.0;
  // rib
  double rib_apex_z_m = 0.0;
  double rib_half_angle_rad = 0.0;    ///< psi of the rib cone (> pi/2)
  double rib_outer_radius_m = 0.0;
  double end_sphere_radius_m = 0.0;
  double end_cap_radius_m = 0.0;
  double end_sphere_offset_m = 0.0;   ///< from the roller middle to the sphere centre, along the axis
  // fidelity
  int slices = 30;
  SliceMethod method = SliceMethod::AlternativeSlicing;
};

/// A roller's place in frame R: mid-point M, axis a (small -> large end), and the radial and
/// circumferential unit vectors of its azimuth.
struct RollerPose {
  Eigen::Vector3d M, a, e_r, e_t;
};

class BearingModel {
 public:
  /// Pose of roller j (azimuth 2 pi j / Z) displaced by u (radial), w (axial), tilt (about e_t).
  RollerPose roller_pose(int j, double u_m, double w_m, double tilt_rad) const noexcept;
  explicit BearingModel(const BearingModelValues& v);  ///< throws std::invalid_argument
  const BearingModelValues& values() const noexcept { return v_; }
  const RollerProfile& profile() const noexcept { return profile_; }
  const LineContactModel& inner_line() const noexcept { return inner_; }
  const LineContactModel& outer_line() const noexcept { return outer_; }
  double rib_Rx_m() const noexcept { return rib_Rx_; }
  double rib_Ry_m() const noexcept { return rib_Ry_; }
  /// The rib's elliptic Hertz contact at the approach delta [m] (hertz_point_contact_approach
  /// with this model's radii): the ellipticity depends on Rx / Ry only, so the contact at
  /// delta is the one at a reference approach scaled by Hertz's laws (load ~ delta^1.5, semi-axes
  /// and pressure ~ delta^0.5; Johnson, Contact Mechanics, 1985, Eq. 4.22-4.26), instead of
  /// solving the ellipticity (60 bisection steps of elliptic integrals) at every evaluation -
  /// half the cost of the load distribution before. Zero for delta <= 0.
  HertzEllipse rib_hertz(double approach_m) const noexcept;
  /// The large end of a roller with mid-point M and axis a (frame of the inner ring).
  RollerEnd roller_end(const Eigen::Vector3d& M, const Eigen::Vector3d& a) const noexcept;
  /// The rib face of the inner ring (its own frame).
  RibFace rib_face() const noexcept;
  /// Closest point and normal of the rib for a roller at (M, a) in the inner ring's frame;
  /// returns the gap there (< 0: interference).
  double rib_closest(const Eigen::Vector3d& M, const Eigen::Vector3d& a, Eigen::Vector3d& p_RC,
                     Eigen::Vector3d& n_R) const noexcept;

 private:
  BearingModelValues v_;
  RollerProfile profile_;
  LineContactModel inner_, outer_;
  double rib_Rx_ = 0.0, rib_Ry_ = 0.0;
  HertzEllipse rib_ref_;  // the rib contact at the reference approach
};

/// External loads on the inner ring and the speed for the centrifugal force.
///
/// The inner ring's tilt is either prescribed (tilt_free = false, the default: a shaft held by
/// its other bearings, as on the paper's test rig; the misalignment angles are imposed and the
/// moment the rollers put on the ring is an output) or free (tilt_free = true: the tilt moment
/// is imposed and the ring finds its tilt).
struct BearingLoads {
  double axial_N = 0.0;        ///< pushes the inner ring towards the apex (-z): seats the rollers
  double radial_N = 0.0;       ///< along +x, at (0, 0, z_M)
  double tilt_moment_Nm = 0.0; ///< about +y (tilt_free)
  double misalignment_x_rad = 0.0;  ///< imposed tilt about x (not tilt_free)
  double misalignment_y_rad = 0.0;  ///< imposed tilt about y (not tilt_free)
  bool tilt_free = false;
  /// Displacement-controlled preload: the inner ring is held at dz = -axial_offset_m (towards
  /// the apex) instead of carrying axial_N; the axial force is then an output.
  bool axial_offset_controlled = false;
  double axial_offset_m = 0.0;
  double cage_speed_rad_s = 0.0;
};

/// Per-roller result.
struct RollerState {
  double u_m = 0.0, w_m = 0.0, tilt_rad = 0.0;  ///< roller DOF (radial, axial, tilt)
  double outer_N = 0.0, inner_N = 0.0, rib_N = 0.0;  ///< contact force magnitudes
  double residual = 0.0;                        ///< |roller equilibrium residual| / load scale
  Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();  ///< reused while it converges (chord Newton)
  bool has_jacobian = false;
};

/// How the quasi-static friction treats the cage.
///  - Off: every roller orbits at the cage speed; no pocket forces (their balance is not closed).
///  - Pocket: every roller orbits at the cage speed, and its pocket takes its circumferential
///    load, with Coulomb friction (Eq. 37) braking its spin. Under a radial load the loaded
///    rollers then push or brake the cage at every azimuth.
///  - FreeRollers: every loaded roller orbits at the speed at which its own contact forces have
///    no circumferential resultant (and spins at the speed that balances its spin moments), so
///    it needs no pocket force; the cage turns at the time-mean orbital speed of a roller
///    travelling once round (the harmonic mean over the azimuths; unloaded rollers coast with
///    the cage). The rollers then drift back and forth in their pockets by
///    BearingFriction::roller_drift_m, which must stay inside the pocket clearance for the model
///    to hold (else Walls). The dynamic simulation
///    (issue 6) shows this regime under the seed paper's combined loads: the rollers move
///    +-6 um in +-170 um pockets and never touch the cage. A loaded roller whose two balances
///    cannot be solved (e.g. one raceway contact only) keeps the cage speed without a pocket force.
///  - Walls: the free rollers in pockets of the model's circumferential clearance. Each roller,
///    travelling once round, walks through its pocket by the difference of its own orbit and
///    the cage's; where its accumulated lead reaches a wall, the wall holds it at the cage's
///    speed (its spin balanced with the pocket's friction, Eq. 37) for the share of the azimuth
///    step it spends there, and it runs free elsewhere. Loaded rollers without an orbit of their
///    own sit at a wall throughout. The cage turns at the speed at which the wall forces have no
///    net moment about the axis (periodic walk: the lead after a revolution equals the lead
///    before it). Free rollers whose drift stays inside the clearance never touch a wall: then it
///    is FreeRollers without locked rollers. Continuous in the loads: a wall's share grows from
///    zero as the drift reaches the clearance.
enum class CageModel { Off = 0, Pocket = 1, FreeRollers = 2, Walls = 3 };

/// The pressure field of the rib cell model (rib_cells > 0).
/// - Hertz: Hertz's elliptic pressure p0 sqrt(1 - x^2/a^2 - y^2/b^2) sampled at the cell centres
///   (scaled to the rib load) wherever the contact ellipse lies wholly on the roller end's
///   spherical cap and on the rib face: the gap there is the quadratic of the two surfaces'
///   radii, which is Hertz's problem, so the half-space solve would return the same field up to
///   its discretisation. Where the cap's or the rib's edge cuts the ellipse (edge loading), the
///   cell field is solved (as Solved).
/// - Solved: the elastic half-space pressure from the gap field by FFT + conjugate gradients,
///   for every roller.
enum class RibPressure { Hertz = 0, Solved = 1 };

struct BearingFriction;

/// The periodic walk of a roller through its cage pocket over one revolution (CageModel::Walls),
/// in the order of travel. Over step k a free roller's lead over its pocket grows by lead[k]
/// until it reaches a wall at +-half_clearance, where the wall holds it for the rest of the
/// step; state[k] = 0 a free roller, +1 / -1 a roller held at the front / back wall throughout
/// (no orbit of its own), 2 an unloaded roller (coasts with the cage: no lead). The walk is
/// periodic: it starts each revolution at the lead it ended the last with. The revolution map is
/// non-decreasing with slope 0 or 1, so the fixed point is found by bisection; where the walk
/// stays inside the clearance (no wall met) every lead in a band is one, and the shares are 0.
/// Writes share[k], the share of step k spent at a wall, and returns the lead at the start.
/// n >= 1, half_clearance > 0; no allocation.
double periodic_pocket_walk(const double* lead, const int* state, int n, double half_clearance,
                            double* share) noexcept;

/// State and workspace (warm start: the previous solution).
class BearingData {
 public:
  explicit BearingData(const BearingModel& model);
  Eigen::Matrix<double, 5, 1> ring = Eigen::Matrix<double, 5, 1>::Zero();  ///< dx, dy, dz, rx, ry
  std::vector<RollerState> rollers;
  std::vector<LineContactData> inner_lines, outer_lines;
  double residual = 0.0;   ///< ring equilibrium residual relative to the load scale
  Eigen::Vector2d reaction_moment_Nm = Eigen::Vector2d::Zero();  ///< rollers on the ring about (0,0,z_M), x and y
  double axial_force_N = 0.0;  ///< axial force the rollers carry (= axial_N in force control)
  bool symmetric = false;      ///< axisymmetric load case: solved for roller 0 and replicated
  int iterations = 0;
  bool has_solution = false;

 private:
  friend int solve_load_distribution(const BearingModel&, BearingData&, const BearingLoads&) noexcept;
  friend int evaluate_bearing_friction(const BearingModel&, BearingData&, const BearingLoads&, double,
                                       const ContactLubricantState&, const ContactLubricantState&,
                                       const FrictionParameters&, const SurfacePair&, const SurfacePair&,
                                       BearingFriction&, int, CageModel, RibPressure) noexcept;
  std::vector<double> orbit_ratio_;      // FreeRollers warm start: roller orbit / pure-rolling cage speed
  std::vector<double> free_spin_ratio_;  // and its spin / pure-rolling spin (NaN: no warm start)
  std::vector<double> free_jacobian_;    // 2 x 2 derivatives of its balances, per roller (chord)
  std::vector<double> spin_ratio_;  // roller spin / its pure-rolling value (warm start)
  double cage_ratio_ = 1.0;         // cage speed / its pure-rolling value (warm start)
  std::vector<double> dSw_, dSc_, dAw_, dAc_;  // spin/cage balance derivatives, reused (chord)
  bool derivatives_valid_ = false;
  // rib cell model: one grid for all rollers (sized by the largest rib load of the point), one
  // workspace (FFT plans), and a warm-start pressure field per roller
  std::shared_ptr<CellContactModel> rib_grid_;
  std::shared_ptr<CellContactData> rib_work_;
  std::vector<std::vector<double>> rib_pressure_;
  double rib_dx_ = 0.0, rib_dy_ = 0.0;
  int rib_n_ = 0;  // the rib grid's cells each way (0: none sized yet)
  std::vector<SliceGeometry> geo_;
  std::vector<double> e_;
  Eigen::MatrixXd ring_jacobian_;  // reused across iterations and operating points (chord Newton)
  int ring_jacobian_mask_ = -1;    // which DOF it belongs to
  // per roller, d(u, w, tilt) / d(ring DOF) from the ring Jacobian's columns: the predictor of
  // the rollers' start for a ring step (rows u, w, tilt; columns the 5 ring DOF)
  std::vector<Eigen::Matrix<double, 3, 5>> roller_sensitivity_;
};

/// Friction of the whole bearing at a solved load distribution (quasi-static, steady state).
///
/// Kinematics: every roller spins at the rate that balances the friction moments about its own
/// axis, and the cage turns at the speed at which the loads the pockets take from the rollers
/// (their friction forces and skew moments) have no net moment about the bearing axis - so
/// light loads show slip.
/// Each slice is evaluated with evaluate_slice() (surface velocities relative to the cage, where
/// the contact is); the rib as one elliptic contact with evaluate_cell(). Rolling resistance
/// (hysteresis, solid rolling, and the EHL rolling force as the moment 2 F R' of equal
/// dissipation) acts through a shift of each slice's normal force towards the inlet, so every
/// contact load is an action-reaction pair and the power balance closes.
struct BearingFriction {
  enum Contact { kOuter = 0, kInner = 1, kRib = 2 };
  enum Mechanism { kEhlSliding = 0, kSolidSliding = 1, kEhlRolling = 2, kSolidRolling = 3, kHysteresis = 4 };
  double inner_speed_rad_s = 0.0;
  double cage_speed_rad_s = 0.0;
  double cage_speed_pure_rolling_rad_s = 0.0;
  std::vector<double> roller_spin_rad_s, roller_spin_pure_rolling_rad_s;
  std::vector<double> roller_orbit_rad_s;  ///< orbital speed of each roller (FreeRollers; else the cage's)
  /// FreeRollers: circumferential excursion of a roller relative to its pocket over one
  /// revolution (max - min of the accumulated orbital lead), at the pitch radius [m]
  double roller_drift_m = 0.0;
  int locked_rollers = 0;  ///< FreeRollers: loaded rollers without an orbit of their own, driven by the cage
  /// FreeRollers: the moment about the bearing axis each free roller's pocket puts on it so that
  /// the cage passes on what driving the locked rollers costs (0 without locked rollers) [N m]
  double pocket_moment_free_Nm = 0.0;
  double drive_torque_Nm = 0.0;       ///< torque the shaft puts on the inner ring
  double outer_ring_torque_Nm = 0.0;  ///< reaction torque on the outer ring (the measured one)
  double power_input_W = 0.0;         ///< drive torque x inner-ring speed
  double power_dissipated_W = 0.0;    ///< sum of the mechanism powers
  double power_W[3][5] = {};          ///< by contact and mechanism
  double cage_power_W = 0.0;          ///< friction in the cage pockets (Eq. 37)
  double Lambda_min[3] = {0, 0, 0};
  double phi_max[3] = {0, 0, 0};
  double cage_residual_Nm = 0.0;      ///< net moment of the rollers on the cage about the axis
  /// Walls: the share of the loaded rollers' time spent at a pocket wall (0: all free; 1: all
  /// held); Pocket: 1; else 0
  double pocket_fraction = 0.0;
  std::vector<double> roller_wall_share;  ///< Walls: the share of each azimuth step spent at a wall
  /// rib cell model: the rollers whose Hertz ellipse at the rib is cut by the edge of the roller
  /// end's cap or of the rib (edge loading; their cell field is solved, see RibPressure)
  int rib_edge_rollers = 0;
};

/// Evaluate the friction at the load distribution in data (solve_load_distribution first).
/// @return 0 on success, 1 if the cage or a roller balance did not converge, -1 bad input.
/// cage: see CageModel (Pocket adds the friction of the cage pockets, Eq. 37).
/// rib_cells = 0 evaluates the rib as one elliptic contact; rib_cells = n > 0 spreads the rib load
/// over the cell model's grid (n x n cells over 3 Hertz semi-axes each way; the pressure field
/// as rib_pressure says, see RibPressure) and evaluates every loaded cell with its own
/// velocities (the drilling friction).
int evaluate_bearing_friction(const BearingModel& model, BearingData& data, const BearingLoads& loads,
                              double inner_speed_rad_s, const ContactLubricantState& lubricant,
                              const FrictionParameters& friction, const SurfacePair& raceway,
                              const SurfacePair& rib, BearingFriction& out, int rib_cells = 0,
                              CageModel cage = CageModel::FreeRollers,
                              RibPressure rib_pressure = RibPressure::Hertz) noexcept;

/// The same with a lubricant state per ring (issue 27, item 6: a contact temperature per ring):
/// the outer raceway's contacts are evaluated with outer_lubricant, the inner raceway's and the
/// rib's (the rib belongs to the inner ring, the cone) with inner_lubricant. The overload above
/// passes one state for both, and gives bit-identical results to this one with two equal states.
int evaluate_bearing_friction(const BearingModel& model, BearingData& data, const BearingLoads& loads,
                              double inner_speed_rad_s, const ContactLubricantState& outer_lubricant,
                              const ContactLubricantState& inner_lubricant, const FrictionParameters& friction,
                              const SurfacePair& raceway, const SurfacePair& rib, BearingFriction& out,
                              int rib_cells = 0, CageModel cage = CageModel::FreeRollers,
                              RibPressure rib_pressure = RibPressure::Hertz) noexcept;

/// Solve the load distribution. An axisymmetric load case (no radial load, no tilt moment, no
/// misalignment, tilt imposed) is solved for one roller and replicated: every roller then
/// carries the same loads by symmetry. @return 0 on convergence (ring residual below 1e-9 of the load
/// scale), 1 if not converged, -1 for invalid loads.
int solve_load_distribution(const BearingModel& model, BearingData& data, const BearingLoads& loads) noexcept;

}  // namespace kegel
