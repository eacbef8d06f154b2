// Slip-scaled acceleration and speed limits.
#include "controller/traction.h"

#include <algorithm>
#include <cmath>

#include "controller/stopping_bound.h"

namespace plantsim::controller {
namespace {

// Moves `from` toward `to`, growing in magnitude by at most `rise`; shrinking is free (braking).
double ramp(double from, double to, double rise) {
  if (std::fabs(to) <= std::fabs(from) && to * from >= 0) return to;  // slowing down or stopping
  const double base = to * from >= 0 ? from : 0.0;  // reversing: through zero, at once
  return std::clamp(to, base - rise, base + rise);
}

}  // namespace

double TractionGovernor::stopping_bound_mps(double free_ahead_m) const {
  if (!p_.stop_within_sight) return std::numeric_limits<double>::infinity();
  // A creep always: the docking approach must still touch the charger it sees ahead.
  return std::max(p_.creep_mps, stopping_speed_mps(free_ahead_m, grip_decel_mps2(),
                                                   p_.stop_reaction_s, p_.stop_margin_m));
}

Twist TractionGovernor::limit(const Twist& wanted, bool slipping, double dt_s,
                              double free_ahead_m) {
  Twist out = grip_limited(wanted, slipping, dt_s);
  const double bound = stopping_bound_mps(free_ahead_m);
  if (out.v_mps > bound) {
    // Slower along the same arc: the turn rate shrinks with the speed (the curvature stays).
    out.omega_radps *= bound / out.v_mps;
    out.v_mps = bound;
  }
  return last_ = out;
}

Twist TractionGovernor::grip_limited(const Twist& wanted, bool slipping, double dt_s) {
  if (!p_.enabled) return wanted;
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
    return out;
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
  return out;
}

}  // namespace plantsim::controller
