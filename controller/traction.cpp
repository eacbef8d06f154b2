// Slip-scaled acceleration and speed limits.
#include "controller/traction.h"

#include <algorithm>
#include <cmath>

namespace plantsim::controller {
namespace {

// Moves `from` toward `to`, growing in magnitude by at most `rise`; shrinking is free (braking).
double ramp(double from, double to, double rise) {
  if (std::fabs(to) <= std::fabs(from) && to * from >= 0) return to;  // slowing down or stopping
  const double base = to * from >= 0 ? from : 0.0;  // reversing: through zero, at once
  return std::clamp(to, base - rise, base + rise);
}

}  // namespace

Twist TractionGovernor::limit(const Twist& wanted, bool slipping, double dt_s) {
  if (!p_.enabled) return last_ = wanted;
  since_slip_s_ += dt_s;
  if (slipping && since_slip_s_ >= p_.slip_hold_s) {
    scale_ = std::max(p_.min_scale, scale_ * p_.slip_scale_factor);
    ++slips_;
    since_slip_s_ = 0;
  } else if (!slipping && since_slip_s_ >= p_.slip_hold_s) {
    scale_ = std::min(1.0, scale_ + p_.recover_per_s * dt_s);
  }
  // Full grip (no slip seen, or recovered): the motors' own limits are the robot's.
  if (scale_ >= 1.0) {
    Twist out = wanted;
    if (p_.full_grip_accel_mps2 > 0 && wanted.v_mps > 0 && last_.v_mps >= 0)
      out.v_mps = ramp(last_.v_mps, wanted.v_mps, p_.full_grip_accel_mps2 * dt_s);
    return last_ = out;
  }
  // Speed and turn rate scaled together (the path's curvature stays), never below a creep:
  // a docking approach must still arrive.
  auto scaled = [&](double x, double creep) {
    return std::copysign(std::max(std::min(std::fabs(x), creep), std::fabs(x) * scale_), x);
  };
  const Twist capped{scaled(wanted.v_mps, p_.creep_mps),
                     scaled(wanted.omega_radps, p_.creep_radps)};
  Twist out;
  out.v_mps = ramp(last_.v_mps, capped.v_mps, scale_ * p_.max_accel_mps2 * dt_s);
  out.omega_radps =
      ramp(last_.omega_radps, capped.omega_radps, scale_ * p_.max_angular_accel_radps2 * dt_s);
  last_ = out;
  return out;
}

}  // namespace plantsim::controller
