// Differential-drive kinematics: body twist (v, omega) to and from wheel rim speeds, and
// saturation that keeps the commanded curvature when a wheel would exceed its limit.
#pragma once

#include <algorithm>
#include <cmath>

namespace plantsim::controller {

struct Twist {
  double v_mps = 0;        ///< forward speed
  double omega_radps = 0;  ///< yaw rate, counter-clockwise positive
};

struct WheelSpeeds {
  double left_mps = 0;   ///< rim speed of the left wheel
  double right_mps = 0;  ///< rim speed of the right wheel
};

inline WheelSpeeds to_wheels(Twist t, double wheel_base_m) {
  return {t.v_mps - 0.5 * wheel_base_m * t.omega_radps,
          t.v_mps + 0.5 * wheel_base_m * t.omega_radps};
}

inline Twist to_twist(WheelSpeeds w, double wheel_base_m) {
  return {0.5 * (w.left_mps + w.right_mps), (w.right_mps - w.left_mps) / wheel_base_m};
}

/// Scales both wheels by the same factor so neither exceeds max_mps (curvature kept).
inline WheelSpeeds saturate(WheelSpeeds w, double max_mps) {
  const double peak = std::max(std::fabs(w.left_mps), std::fabs(w.right_mps));
  if (peak <= max_mps) return w;
  const double s = max_mps / peak;
  return {w.left_mps * s, w.right_mps * s};
}

}  // namespace plantsim::controller
