// Travel along the plan with the arc ahead checked, and what it does while blocked.
#include "controller/path_follower.h"

#include <algorithm>
#include <cmath>

#include "util/component_failure.h"

namespace plantsim::controller {

double uncertainty_speed_fraction(const PathFollowParams& p, double position_sigma_m) {
  if (!(position_sigma_m > p.confident_sigma_m)) return 1.0;
  if (!(p.uncertain_sigma_m > p.confident_sigma_m) || position_sigma_m >= p.uncertain_sigma_m)
    return p.uncertain_speed_fraction;
  const double share =
      (position_sigma_m - p.confident_sigma_m) / (p.uncertain_sigma_m - p.confident_sigma_m);
  return 1.0 - share * (1.0 - p.uncertain_speed_fraction);
}

PathFollower::PathFollower(std::unique_ptr<LocalController> tracker, PathFollowParams params,
                           InPlaceTurn turn, std::vector<Vec2> path)
    : tracker_(std::move(tracker)), params_(params), turn_(turn) {
  replace_path(std::move(path));
}

void PathFollower::replace_path(std::vector<Vec2> path) {
  try {
    tracker_->set_path(std::move(path));
  } catch (...) {
    if (tracker_->plugin_origin().empty()) throw;  // a built-in's: plantsim's own error
    util::rethrow_as_component_failure(tracker_->plugin_origin());
  }
}

FollowStep PathFollower::step(const DockingInput& in, MotionGuard& guard,
                              const YieldParams& yield) {
  FollowStep out;
  TrackingCommand t;
  try {
    t = tracker_->step({in.pose, in.speed_mps, in.yaw_rate_radps, in.dt_s, &in.nearby_obstacles});
  } catch (...) {
    if (tracker_->plugin_origin().empty()) throw;  // a built-in's: plantsim's own error
    util::rethrow_as_component_failure(tracker_->plugin_origin());
  }
  // Slower when unsure where it is: the same arc, at a share of the speed.
  const double slow = uncertainty_speed_fraction(params_, in.position_sigma_m);
  t.twist = {slow * t.twist.v_mps, slow * t.twist.omega_radps};
  out.cross_track_error_m = t.cross_track_error_m;
  out.twist = t.twist;
  const double v = std::max(std::fabs(t.twist.v_mps), std::fabs(in.speed_mps));
  // Never beyond the corner where it will stop and turn in place: a straight arc past it
  // would clip what the path itself turns away from.
  const double braking = guard.braking_distance_m(v);
  const double ahead = std::min(braking + guard.params().check_extra_m,
                                std::max(braking, t.straight_ahead_m) + 0.05);
  // Slow (starting or slowing) robots take longer to get there: never assume less than
  // a walking pace's worth of time for the obstacles to move.
  const double travel_speed =
      std::max(0.5 * (std::fabs(in.speed_mps) + std::fabs(t.twist.v_mps)), 0.1);
  if (!arc_clear(in.pose, t.twist, travel_speed, ahead, guard.radius_m(), in.nearby_obstacles)) {
    hold_blocked(in, t, guard, yield, out);
    return out;
  }
  blocked_time_s_ = 0;
  guard.note_clear(in.dt_s);
  if (std::fabs(t.twist.omega_radps) < 0.05)
    straight_run_m_ += t.twist.v_mps * in.dt_s;
  else
    straight_run_m_ = 0;
  out.goal_reached = t.goal_reached;
  return out;
}

void PathFollower::hold_blocked(const DockingInput& in, const TrackingCommand& t,
                                MotionGuard& guard, const YieldParams& yield, FollowStep& out) {
  guard.note_blocked();
  out.twist = {};
  out.blocked = true;
  // Stopped in something's way (it does not yield): back out along the stretch just driven.
  const MotionGuardParams& g = guard.params();
  const bool is_threatened =
      threatened(yield, in.pose.position(), g.footprint_radius_m + 0.5 * g.safety_margin_m,
                 in.nearby_obstacles);
  const Twist back{-yield.yield_speed_mps, 0.0};
  if (straight_run_m_ > 0.05 && is_threatened &&
      guard.clear(in.pose, in.speed_mps, back, in.nearby_obstacles)) {
    // ... only while what it senses leaves that stretch clear (a person may be behind too).
    out.twist = back;
    straight_run_m_ -= yield.yield_speed_mps * in.dt_s;
  } else if (!is_threatened && std::fabs(t.carrot_bearing_rad) > turn_.tolerance_rad) {
    // Nothing coming: face the carrot in place (a disk turns without sweeping anything),
    // so that the next arc is straight, not one that bulges into what blocked the curve.
    out.twist = {0.0,
                 std::clamp(2.0 * t.carrot_bearing_rad, -turn_.speed_radps, turn_.speed_radps)};
  }
  blocked_time_s_ += in.dt_s;
  if (blocked_time_s_ >= params_.replan_after_s) {
    out.replan_requested = true;
    blocked_time_s_ = 0;
  }
}

}  // namespace plantsim::controller
