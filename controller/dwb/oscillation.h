// DWB's Oscillation critic as nav2_dwb_controller has it: once the sent command's forward speed
// (or, while nearly stationary, its turn) has reversed, the opposite sign is refused until the
// robot has moved oscillation_reset_dist or turned oscillation_reset_angle since that reversal.
// Turns are not tracked while driving on: a robot that steers left then right along a corridor
// is following it, not oscillating.
#pragma once

#include "controller/diff_drive.h"
#include "geometry/vec2.h"

namespace plantsim::controller::dwb {

struct OscillationParams {
  double reset_dist_m = 0.05;      ///< oscillation_reset_dist
  double reset_angle_rad = 0.2;    ///< oscillation_reset_angle
  double x_only_threshold = 0.05;  ///< m/s: faster than this, turns are not tracked
};

class OscillationCritic {
 public:
  explicit OscillationCritic(OscillationParams p = {}) : p_(p) {}

  /// Would sending `command` now reverse a reversal?
  bool oscillating(const Twist& command) const {
    return x_.oscillating(command.v_mps) || theta_.oscillating(command.omega_radps);
  }
  /// After a cycle: the command sent from `pose`.
  void sent(const Twist& command, const geom::Pose2& pose);
  void reset() { x_ = {}, theta_ = {}; }

 private:
  /// The sign of one velocity over time, and which sign a reversal left allowed.
  struct Trend {
    int sign = 0;
    bool positive_only = false, negative_only = false;
    bool update(double v);  ///< true when this velocity reversed the sign
    bool oscillating(double v) const {
      return (positive_only && v < 0) || (negative_only && v > 0);
    }
    bool flipped() const { return positive_only || negative_only; }
  };

  OscillationParams p_;
  Trend x_, theta_;
  geom::Pose2 flipped_at_;  ///< where the last reversal was sent
};

}  // namespace plantsim::controller::dwb
