// atan2 to within kBoundedAtan2ErrorRad, at a fraction of libm's cost, for callers that widen
// their own tolerance by that bound (the ray fan's angular extents: a box's corners, twice per
// box, three fans a scan). Not for anything whose result must be libm's to the last bit.
#pragma once

#include <cmath>

namespace plantsim::geom {

/// The largest difference from std::atan2 (radians); tests/test_geometry.cpp holds it to this.
inline constexpr double kBoundedAtan2ErrorRad = 1e-9;

/// The angle of (x, y) in [-pi, pi], as std::atan2(y, x) to within kBoundedAtan2ErrorRad (at
/// the cut along the negative x axis either end may be given, as for any rounding there).
inline double bounded_atan2(double y, double x) {
  const double ax = std::fabs(x), ay = std::fabs(y);
  const bool steep = ay > ax;
  const double num = steep ? ax : ay, den = steep ? ay : ax;
  if (!(den > 0) || !std::isfinite(den)) return std::atan2(y, x);  // origin, inf, NaN
  double a = num / den;                                            // in [0, 1]
  // Above tan(pi/12), atan(a) = pi/6 + atan((a sqrt3 - 1) / (a + sqrt3)): the argument left is
  // within +-tan(pi/12) = 0.268, where the series' first omitted term, a^15 / 15, is 2e-10.
  constexpr double kTanPi12 = 0.26794919243112270, kSqrt3 = 1.7320508075688772;
  double base = 0;
  if (a > kTanPi12) {
    a = (a * kSqrt3 - 1.0) / (a + kSqrt3);
    base = M_PI / 6;
  }
  const double z = a * a;
  const double series =
      a * (1.0 +
           z * (-1.0 / 3 +
                z * (1.0 / 5 + z * (-1.0 / 7 + z * (1.0 / 9 + z * (-1.0 / 11 + z * (1.0 / 13)))))));
  double angle = base + series;
  if (steep) angle = M_PI / 2 - angle;
  if (x < 0) angle = M_PI - angle;
  return std::signbit(y) ? -angle : angle;
}

}  // namespace plantsim::geom
