// Driving within the grip the floor gives. The robot does not know the floor's friction; it
// knows when its wheels slip (perception compares the encoders with the gyro and the scan).
// The governor sits between the travel mode and the motors. Until a slip is seen it passes the
// twist through (the motors' limits are the robot's) but for a soft start of forward speed,
// because the first spin on an unknown floor is the one nothing sees; each slip scales the speed
// down and limits how fast the commanded twist may grow (acceleration, turn-in-place) to the scaled
// limits; they recover slowly while no slip is seen. Braking is never limited: stopping
// for an obstacle always gets the motors' full deceleration. Last, forward speed is bounded by
// what the robot can stop from within the free range its lidar reports ahead, at the braking
// deceleration its learnt grip allows (stop_decel_mps2 times the slip scale; stopping_bound.h).
// Pure: no physics, no truth.
#pragma once

#include <limits>

#include "controller/diff_drive.h"

namespace plantsim::controller {

struct TractionParams {
  bool enabled = true;
  double max_accel_mps2 = 1.0;  ///< forward speed may grow this fast (scaled; at most the robot's)
  double max_angular_accel_radps2 = 3.0;  ///< turning rate may grow this fast (scaled)
  double slip_scale_factor = 0.6;         ///< each slip multiplies the scale by this ...
  double min_scale = 0.15;                ///< ... down to this
  double slip_hold_s = 0.5;               ///< slips closer together than this are one
  double recover_per_s = 0.03;            ///< scale regained per second without slip
  double creep_mps = 0.1;  ///< speeds up to this are never scaled down (docking, pressing)
  double creep_radps = 0.3;
  /// At full grip forward speed grows at most this fast (0: the motors' limit); reversing, to
  /// yield, keeps the motors' limit. The robot cannot know the floor's grip before its wheels
  /// spin, and a spin while driving straight along a lone wall is seen by nothing it has.
  double full_grip_accel_mps2 = 0.3;
  /// Forward speed at most what stops within the free range ahead (docs/config.md, "Stopping
  /// within sight"): v t + v^2 / (2 a) <= free - margin, a = stop_decel_mps2 x the slip scale.
  bool stop_within_sight = true;
  double stop_decel_mps2 = 0.5;   ///< braking counted on at full grip (a floor not yet learnt)
  double stop_margin_m = 1.0;     ///< kept between the stopped footprint and what it saw
  double stop_reaction_s = 0.15;  ///< driven at speed before braking takes hold (scan, period)
};

class TractionGovernor {
 public:
  explicit TractionGovernor(TractionParams p) : p_(p) {}
  /// The twist to send the motors this control period, given the wanted one, whether
  /// perception saw the wheels slip since the last period and the free range ahead of the
  /// footprint (m; +inf: nothing seen to stop for).
  Twist limit(const Twist& wanted, bool slipping, double dt_s,
              double free_ahead_m = std::numeric_limits<double>::infinity());
  double scale() const { return scale_; }  ///< 1: full speed and acceleration
  /// The braking deceleration the learnt grip allows (m/s^2): stop_decel_mps2 x scale().
  double grip_decel_mps2() const { return p_.stop_decel_mps2 * scale_; }
  /// The forward speed bound for `free_ahead_m` at the learnt grip (never below creep_mps).
  double stopping_bound_mps(double free_ahead_m) const;
  int slips() const { return slips_; }  ///< slip events met

 private:
  /// The slip-scaled limits alone (the stopping bound applies after).
  Twist grip_limited(const Twist& wanted, bool slipping, double dt_s);
  TractionParams p_;
  Twist last_;
  double scale_ = 1.0;
  double since_slip_s_ = 1e9;
  int slips_ = 0;
};

}  // namespace plantsim::controller
