// Closed-form Hertz point (elliptic) contact: the cheaper fidelity level of the rib contact.
//
// Ellipticity k = a/b from the curvature ratio by solving Hertz's relation exactly (the seed
// paper's Eq. 32 is its Hamrock-Brewe approximation, 3 % off at k = 1), then the Hertz relations with the complete elliptic integrals K(e), E(e) of the
// eccentricity e^2 = 1 - 1/k^2 (Hamrock and Dowson's form; exact for k = 1):
//   a = (6 k^2 E Q R / (pi E'))^(1/3),  b = (6 E Q R / (pi k E'))^(1/3),
//   delta = K (9 / (2 E R) (Q / (pi k E'))^2)^(1/3),  p0 = 3 Q / (2 pi a b),
// with 1/R = 1/Rx + 1/Ry, Rx the smaller radius (b along x).
#pragma once

namespace kegel {

struct HertzEllipse {
  double load_N = 0.0;
  double approach_m = 0.0;
  double semi_major_m = 0.0;   ///< a, along the direction of the larger radius
  double semi_minor_m = 0.0;   ///< b
  double max_pressure_Pa = 0.0;
  double ellipticity = 1.0;    ///< k = a / b
};

/// Exact ellipticity k = a/b >= 1 for the radius ratio Ry/Rx >= 1.
double hertz_ellipticity(double radius_ratio) noexcept;

/// Contact for a given load Q > 0 (radii > 0; the order of Rx, Ry does not matter).
HertzEllipse hertz_point_contact_load(double Rx_m, double Ry_m, double E_reduced_Pa, double Q_N) noexcept;
/// Contact for a given approach (interference) delta; zero load for delta <= 0.
HertzEllipse hertz_point_contact_approach(double Rx_m, double Ry_m, double E_reduced_Pa,
                                          double delta_m) noexcept;

}  // namespace kegel
