// The arc check with braking distance, and stops counted once per encounter.
#include "controller/motion_guard.h"

#include <algorithm>
#include <cmath>

namespace plantsim::controller {

bool MotionGuard::clear(const Pose2& pose, double speed_mps, const Twist& twist,
                        const std::vector<MovingBox>& boxes) {
  const double v = std::max(std::fabs(twist.v_mps), std::fabs(speed_mps));
  const double ahead = braking_distance_m(v) + params_.check_extra_m;
  if (arc_clear(pose, twist, std::max(v, 0.1), ahead, radius_m(), boxes)) return true;
  note_blocked();
  return false;
}

void MotionGuard::note_blocked() {
  if (!was_blocked_ && clear_time_s_ >= 1.0) ++stops_;
  was_blocked_ = true;
  clear_time_s_ = 0;
}

void MotionGuard::note_clear(double dt_s) {
  was_blocked_ = false;
  clear_time_s_ += dt_s;
}

}  // namespace plantsim::controller
