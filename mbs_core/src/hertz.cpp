#include "kegel/core/hertz.hpp"

#include <algorithm>
#include <cmath>

namespace kegel {
namespace {
constexpr double kPi = 3.14159265358979323846;

struct Shape {
  double k, E, K, R;
};

// Exact ellipticity: Ry/Rx = (k^2 E(e) - K(e)) / (K(e) - E(e)), e^2 = 1 - 1/k^2 (Hertz; see
// Hamrock and Dowson 1981). The seed paper's Eq. 32 approximates its solution to a few per cent;
// kegel solves it (bisection on e, 60 steps) and uses Eq. 32 only where the paper does (Eq. 31).
double exact_ellipticity(double ratio) noexcept {
  if (!(ratio > 1.0 + 1e-12)) return 1.0;
  auto f = [&](double e) {
    const double K = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
    const double k2 = 1.0 / (1.0 - e * e);
    return (k2 * E - K) / (K - E) - ratio;
  };
  double lo = 1e-6, hi = 1.0 - 1e-15;  // f(lo) ~ 0.75 lo^2 + 1 - ratio < 0, f(hi) large
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  const double e = 0.5 * (lo + hi);
  return 1.0 / std::sqrt(1.0 - e * e);
}

Shape shape(double Rx, double Ry) noexcept {
  const double r1 = std::min(Rx, Ry), r2 = std::max(Rx, Ry);
  Shape s;
  s.k = exact_ellipticity(r2 / r1);
  const double e = std::sqrt(std::max(0.0, 1.0 - 1.0 / (s.k * s.k)));
  s.K = std::comp_ellint_1(e);
  s.E = std::comp_ellint_2(e);
  s.R = 1.0 / (1.0 / Rx + 1.0 / Ry);
  return s;
}

HertzEllipse from_load(const Shape& s, double Ep, double Q) noexcept {
  HertzEllipse h;
  h.load_N = Q;
  h.ellipticity = s.k;
  h.semi_major_m = std::cbrt(6.0 * s.k * s.k * s.E * Q * s.R / (kPi * Ep));
  h.semi_minor_m = std::cbrt(6.0 * s.E * Q * s.R / (kPi * s.k * Ep));
  const double f = Q / (kPi * s.k * Ep);
  h.approach_m = s.K * std::cbrt(9.0 / (2.0 * s.E * s.R) * f * f);
  h.max_pressure_Pa = 3.0 * Q / (2.0 * kPi * h.semi_major_m * h.semi_minor_m);
  return h;
}
}  // namespace

double hertz_ellipticity(double ratio) noexcept { return exact_ellipticity(ratio); }

HertzEllipse hertz_point_contact_load(double Rx, double Ry, double Ep, double Q) noexcept {
  if (!(Q > 0.0)) return {};
  return from_load(shape(Rx, Ry), Ep, Q);
}

HertzEllipse hertz_point_contact_approach(double Rx, double Ry, double Ep, double delta) noexcept {
  if (!(delta > 0.0)) return {};
  const Shape s = shape(Rx, Ry);
  // invert delta = K (9/(2 E R))^(1/3) (Q / (pi k E'))^(2/3)
  const double c = s.K * std::cbrt(9.0 / (2.0 * s.E * s.R));
  const double Q = kPi * s.k * Ep * std::pow(delta / c, 1.5);
  return from_load(s, Ep, Q);
}

}  // namespace kegel
