// The docking stack's travel to the staging pose: its local controller (pure pursuit by default,
// local_controller.h) along the plan, slowed as the
// estimate grows uncertain, stopping short of what moves into the arc ahead (never checking past
// the corner where it will stop and turn); while stopped, it backs out along the stretch just
// driven from something that will not yield, or faces the carrot in place, and asks for a new
// plan when the block lasts.
#pragma once

#include <memory>
#include <vector>

#include "controller/docking_input.h"
#include "controller/local_controller.h"
#include "controller/motion_guard.h"
#include "controller/yield_policy.h"

namespace plantsim::controller {

struct PathFollowParams {
  double replan_after_s = 3.0;  ///< blocked this long: ask for a new plan
  // Travel slows as the estimate grows uncertain, instead of stopping.
  double confident_sigma_m = 0.05;  ///< full speed up to this 1-sigma of the position estimate
  double uncertain_sigma_m = 0.5;   ///< ... slowed linearly to uncertain_speed_fraction at this
                                    ///< and beyond
  double uncertain_speed_fraction = 0.6;
};

/// How it turns in place to face the carrot while blocked with nothing coming: the docking's
/// own turn onto the axis (docking.align_tolerance_rad, align_speed_radps).
struct InPlaceTurn {
  double tolerance_rad = 0.01;
  double speed_radps = 0.8;
};

/// The share of travel speed an estimate of this 1-sigma allows (1 when confident).
double uncertainty_speed_fraction(const PathFollowParams& p, double position_sigma_m);

struct FollowStep {
  Twist twist;
  double cross_track_error_m = 0;
  bool blocked = false;           ///< stopped because the arc ahead is not clear
  bool replan_requested = false;  ///< blocked long enough: plan again around what is seen
  bool goal_reached = false;      ///< at the path's end (the staging pose)
};

class PathFollower {
 public:
  PathFollower(std::unique_ptr<LocalController> tracker, PathFollowParams params, InPlaceTurn turn,
               std::vector<Vec2> path);

  FollowStep step(const DockingInput& in, MotionGuard& guard, const YieldParams& yield);
  /// A new path from wherever the robot is (after a replan).
  void replace_path(std::vector<Vec2> path);

 private:
  void hold_blocked(const DockingInput& in, const TrackingCommand& t, MotionGuard& guard,
                    const YieldParams& yield, FollowStep& out);

  std::unique_ptr<LocalController> tracker_;
  PathFollowParams params_;
  InPlaceTurn turn_;
  double blocked_time_s_ = 0;
  double straight_run_m_ = 0;  // driven straight ahead since the last turn: free to reverse into
};

}  // namespace plantsim::controller
