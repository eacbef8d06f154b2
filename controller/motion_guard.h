// The docking stack's collision checker (Nav2's RPP keeps one apart too): whether the arc a twist
// drives meets something sensed within the braking distance and a margin, for the robot's disk
// and a safety margin; and the count of stops, one per encounter (a tracked obstacle's velocity
// wobbles, and the check with it: a go of under a second between two blocks is the same stop).
#pragma once

#include <vector>

#include "controller/collision_check.h"
#include "controller/path_geometry.h"

namespace plantsim::controller {

struct MotionGuardParams {
  double footprint_radius_m = 0.2;  ///< robot disk, for the arc check (set from the world)
  double safety_margin_m = 0.15;    ///< extra clearance the arc must keep
  double max_decel_mps2 = 1.0;      ///< braking, to size the arc checked ahead
  double check_extra_m = 0.4;       ///< checked beyond the braking distance
};

class MotionGuard {
 public:
  explicit MotionGuard(MotionGuardParams params) : params_(params) {}

  /// True when the arc of `twist` from `pose` stays clear of `boxes` for the braking distance
  /// at the larger of the commanded and current speeds plus check_extra_m; false, and the block
  /// noted, otherwise.
  bool clear(const Pose2& pose, double speed_mps, const Twist& twist,
             const std::vector<MovingBox>& boxes);
  /// The disk the arc must keep clear: the footprint and the safety margin.
  double radius_m() const { return params_.footprint_radius_m + params_.safety_margin_m; }
  double braking_distance_m(double speed_mps) const {
    return speed_mps * speed_mps / (2.0 * params_.max_decel_mps2);
  }
  const MotionGuardParams& params() const { return params_; }

  /// A block met: counted as a stop unless it follows the last one closely.
  void note_blocked();
  void note_clear(double dt_s);
  int stops() const { return stops_; }

 private:
  MotionGuardParams params_;
  int stops_ = 0;
  bool was_blocked_ = false;
  double clear_time_s_ = 1e9;  // driven unblocked since the last block
};

}  // namespace plantsim::controller
