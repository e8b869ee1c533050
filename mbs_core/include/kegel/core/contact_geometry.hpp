// Contact geometry of the bodies of a tapered roller bearing for any relative pose.
//
// Frames: R = ring frame, its z axis the ring's axis; vectors carry their frame in the name
// (p_RM: point M in frame R; a_R: roller axis direction in frame R), as in Drake.
//
// * raceway_slice_geometry(): roller slices (discs perpendicular to the roller axis) against a
//   raceway cone. For each slice: contact point on the raceway, contact normal, interference
//   (overlap of the undeformed bodies), the local tangent directions (rolling and along the
//   contact line) and the reduced radius in the rolling direction. Tilt and skew of the roller
//   enter through its axis direction; the disc's extent towards the cone, rho sqrt(1 - (a.n)^2),
//   is exact for a disc ("its penetration into the contour of the opposite slice").
// * rib_gap(): the undeformed gap between the roller's spherical large end and the rib cone on
//   a cell grid in the tangent plane at the closest point, by exact ray intersections (so the
//   elongated or crescent-shaped contact windows of the rib are represented); input of the cell
//   model.
// * cage_pocket_contact(): the roller against the two flat side walls of its cage pocket.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "kegel/core/line_contact.hpp"
#include "kegel/core/slice.hpp"
#include "kegel/core/tribology.hpp"

namespace kegel {

/// A cone of revolution about the z axis of frame R: the points A + s (cos psi e_z + sin psi e_r),
/// s > 0, with A = (0, 0, apex_z). psi in (0, pi/2) opens towards +z (raceways); psi in
/// (pi/2, pi) opens towards -z (a rib face whose normal is close to the axis).
/// Its outward normal in the meridional plane is n_out = -sin psi e_z + cos psi e_r.
struct Cone {
  double apex_z_m = 0.0;
  double half_angle_rad = 0.0;
};

/// Which side of the cone the roller lies on.
enum class RacewaySide {
  Inner = 0,  ///< inner ring raceway (and rib): the roller lies on the side of n_out
  Outer = 1,  ///< outer ring raceway (cup): the roller lies on the side of -n_out
};

/// Roller shape: a truncated cone with a profile (drop) along its axis.
struct RollerShape {
  double mean_radius_m = 0.0;    ///< radius at mid-length
  double half_angle_rad = 0.0;   ///< cone half-angle gamma (radius grows towards +axis)
  double length_m = 0.0;
};

/// One slice's contact geometry (frame R).
struct SliceGeometry {
  double xi_m = 0.0;                    ///< slice position along the roller axis from its middle
  double interference_m = 0.0;          ///< > 0: the undeformed bodies overlap
  Eigen::Vector3d p_RC = Eigen::Vector3d::Zero();   ///< contact point on the raceway
  Eigen::Vector3d n_R = Eigen::Vector3d::Zero();    ///< unit normal, raceway -> roller
  Eigen::Vector3d t_roll_R = Eigen::Vector3d::Zero();  ///< rolling direction (circumferential)
  Eigen::Vector3d t_line_R = Eigen::Vector3d::Zero();  ///< along the contact line
  double reduced_radius_m = 0.0;        ///< R' in the rolling direction
};

/// Slice geometry for a roller at pose (p_RM, a_R) against a raceway cone.
/// @param xi_m   slice positions along the roller axis (n values), e.g. LineContactModel::position_m
/// @param out    n results (resized by the caller; nothing is allocated here)
void raceway_slice_geometry(const RollerShape& roller, const RollerProfile& profile,
                            const Eigen::Vector3d& p_RM, const Eigen::Vector3d& a_R,
                            const Cone& raceway, RacewaySide side, const double* xi_m, int n,
                            SliceGeometry* out) noexcept;

/// The tribology input of one slice (evaluate_slice) from its geometry, its line load q (from
/// solve_line_contact) and the velocities of the roller's and the ring's material points at the
/// contact point (frame R). Velocities are projected on the rolling direction (x) and the
/// contact line (y); the approach velocity is the relative velocity along -n.
SliceInput make_slice_input(const SliceGeometry& g, double line_load_N_m, double width_m,
                            const Eigen::Vector3d& v_roller_R, const Eigen::Vector3d& v_ring_R) noexcept;

/// The roller's large end: a spherical cap (centre p_RE on the roller axis a_R, radius R_e)
/// limited to points within cap_radius of the roller axis.
struct RollerEnd {
  Eigen::Vector3d p_RE = Eigen::Vector3d::Zero();
  Eigen::Vector3d a_R = Eigen::Vector3d::UnitZ();
  double sphere_radius_m = 0.0;
  double cap_radius_m = 0.0;
};

/// The rib face: a cone (psi in (pi/2, pi) for the large rib of a cone) up to outer_radius.
struct RibFace {
  Cone cone;
  double outer_radius_m = 0.0;
};

/// Undeformed gap between the roller end and the rib face on a cell grid in the tangent plane
/// at the rib point closest to the sphere: nx x ny cells of size dx x dy, x along the rib
/// generator, y circumferential. Gaps come from exact ray intersections along the normal, so
/// the truncation of the contact by the cap edge and the rib top (a crescent) is represented;
/// cells off the cap or the rib get a gap of one sphere radius.
/// Returns the minimum gap, exact at the foot of the sphere centre (< 0: the undeformed bodies
/// overlap, the rigid interference is -minimum); h0 (nx * ny, row-major) receives the gap minus
/// that minimum (>= 0) for solve_cell_contact(), whose approach is then the interference; p_RC the closest rib point; n_R the normal (rib -> roller).
/// cells (nx * ny, optional): only the cells where it is non-zero are evaluated, the others get
/// the far gap (one sphere radius minus the minimum), as if off the cap.
double rib_gap(const RollerEnd& end, const RibFace& rib, int nx, int ny, double dx, double dy,
               double* h0, Eigen::Vector3d& p_RC, Eigen::Vector3d& n_R,
               const unsigned char* cells = nullptr) noexcept;

/// A cage pocket: two flat side walls symmetric to the pocket's centre plane (which contains the
/// ring axis), at +-(half_width + y tan(taper)) from it, so that they follow the taper of the
/// roller. Frame P: x circumferential, y along the pocket (roller axis direction, towards the
/// large end), z radial; origin at the pocket centre.
struct CagePocket {
  double half_width_m = 0.0;         ///< half the distance between the two walls at y = 0
  double taper_rad = 0.0;            ///< wall half-angle (the roller's half-angle)
  double d_max_Ns_m = 0.0;           ///< damping (Eq. 2-3) per contact point
  double delta_max_m = 1e-6;
  tribology::CubicFrictionLaw friction{0.1, 0.1, 1e-3, 2e-3};  ///< Eq. 37
};

/// Result of the roller / cage-pocket contact, in the pocket frame P.
struct CagePocketResult {
  Eigen::Vector3d force_on_roller_P = Eigen::Vector3d::Zero();
  Eigen::Vector3d moment_on_roller_P = Eigen::Vector3d::Zero();  ///< about the roller mid-point
  double normal_force_N = 0.0;       ///< sum over the contact points
  double max_penetration_m = 0.0;
};

/// Roller (mid-point p_PM, axis a_P, radius along the axis from shape, velocity field
/// v_PM + w_P x r) against the two pocket walls, checked at points along the roller
/// (n_points >= 2, each standing for a length L / n_points of the roller). Normal force of each
/// point: its share 1/n_points of Palmgren's line-contact law over the whole length (steel cage
/// web on the roller), so the total does not depend on n_points; parametric damping (Eq. 1-3) and regularised Coulomb friction (Eq. 37) against the sliding velocity of the
/// roller surface on the wall. Velocities are relative to the cage (frame P fixed in the cage).
CagePocketResult cage_pocket_contact(const RollerShape& roller, const CagePocket& pocket,
                                     const Eigen::Vector3d& p_PM, const Eigen::Vector3d& a_P,
                                     const Eigen::Vector3d& v_PM, const Eigen::Vector3d& w_P,
                                     int n_points) noexcept;

}  // namespace kegel
