// The docking phases, with the travel, the arc check, giving way and the dock's pose left to
// their collaborators.
#include "controller/docking.h"

#include <algorithm>
#include <cmath>

#include "controller/collision_check.h"
#include "controller/pure_pursuit_controller.h"

namespace plantsim::controller {

std::string_view to_string(DockPhase p) {
  switch (p) {
    case DockPhase::kTravel:
      return "travel";
    case DockPhase::kAlign:
      return "align";
    case DockPhase::kApproach:
      return "approach";
    case DockPhase::kBackOff:
      return "back_off";
    case DockPhase::kDocked:
      return "docked";
    case DockPhase::kUndock:
      return "undock";
    case DockPhase::kUndocked:
      return "undocked";
    case DockPhase::kFailed:
      return "failed";
  }
  return "unknown";
}

std::string_view to_string(DockFailure f) {
  switch (f) {
    case DockFailure::kNone:
      return "none";
    case DockFailure::kRetriesExhausted:
      return "retries exhausted";
    case DockFailure::kBlocked:
      return "back-off blocked";
    case DockFailure::kUnsettled:
      return "never settled after a displacement";
    case DockFailure::kNotLocalized:
      return "never localised again after a displacement";
    case DockFailure::kUndockBlocked:
      return "undock blocked";
  }
  return "unknown";
}

void DockingController::fail(DockFailure why) {
  phase_ = DockPhase::kFailed;
  failure_ = why;
}

DockingController::DockingController(PurePursuitParams tracking, DockingParams docking,
                                     std::vector<Vec2> path, Pose2 charger_on_map)
    : DockingController(make_pure_pursuit(tracking), docking, std::move(path), charger_on_map) {}

DockingController::DockingController(std::unique_ptr<LocalController> tracker,
                                     DockingParams docking, std::vector<Vec2> path,
                                     Pose2 charger_on_map)
    : follower_(std::move(tracker), docking.travel,
                {docking.align_tolerance_rad, docking.align_speed_radps}, std::move(path)),
      params_(docking),
      guard_(docking.guard),
      dock_(docking.filter, docking.staging_distance_m, charger_on_map),
      dock_map_(charger_on_map) {}

Vec2 DockingController::in_dock_frame(Vec2 p) const { return to_robot_frame(dock_.pose(), p); }

void DockingController::replace_path(std::vector<Vec2> path) {
  if (phase_ == DockPhase::kTravel) follower_.replace_path(std::move(path));
}

void DockingController::miss() {
  // Always back away from the charger first; after the last allowed retry, fail there.
  if (retries_ >= params_.max_retries)
    giving_up_ = true;
  else {
    ++retries_;
    events_.retried = true;
  }
  phase_ = DockPhase::kBackOff;
}

DockingCommand DockingController::recover(const DockingInput& in) {
  DockingCommand out;
  out.phase = phase_;
  out.blocked = true;
  // Stopped until the estimate has settled: nothing touching, localised, for a while. A robot
  // that never settles gives up where it stands.
  const bool unsettled = in.displaced || in.bumper_front || in.bumper_rear || !in.localized;
  if (unsettled)
    last_unsettled_by_localization_ = !in.localized && !in.bumper_front && !in.bumper_rear;
  settled_s_ = unsettled ? 0.0 : settled_s_ + in.dt_s;
  unsettled_s_ += in.dt_s;
  if (settled_s_ >= params_.settle_s) {
    // From wherever it now is: travelling again, the charger placed anew at the staging pose
    // (the odometry never saw the shove, so the dock estimate in its frame is stale).
    recovering_ = false;
    ++recoveries_;
    events_.recovered = true;
    phase_ = DockPhase::kTravel;
    dock_.forget();
    pressing_ = false;
    out.recover_requested = true;
    out.phase = phase_;
  } else if (unsettled_s_ > (last_unsettled_by_localization_ ? params_.relocalize_timeout_s
                                                             : params_.stuck_timeout_s)) {
    recovering_ = false;
    fail(last_unsettled_by_localization_ ? DockFailure::kNotLocalized : DockFailure::kUnsettled);
    out.phase = phase_;
  } else if (!in.localized && !in.bumper_front && !in.bumper_rear) {
    // Not knowing where it is: turn in place, so that the scans sweep all round for the
    // global match (a disk turning in place sweeps nothing; the guard checks other footprints).
    const Twist look_round{0.0, 0.4};
    if (guard(in, look_round, false)) out.twist = look_round;
  }
  return out;
}

bool DockingController::yield(const DockingInput& in, DockingCommand& out) {
  if (!threatened_by_movers(params_.yield, in.pose.position(),
                            params_.guard.footprint_radius_m + 0.5 * params_.guard.safety_margin_m,
                            in.nearby_obstacles))
    return false;
  const Twist back{-params_.yield.yield_speed_mps, 0.0};
  out.twist = guard(in, back, false) ? back : Twist{};
  out.blocked = true;
  return true;
}

DockingCommand DockingController::step(const DockingInput& in) {
  events_ = {};
  const int stops_before = guard_.stops();
  DockingCommand out = step_phase(in);
  events_.stopped = guard_.stops() > stops_before;
  out.events = events_;
  return out;
}

DockingCommand DockingController::step_phase(const DockingInput& in) {
  const bool docking = phase_ != DockPhase::kDocked && phase_ != DockPhase::kFailed &&
                       phase_ != DockPhase::kUndock && phase_ != DockPhase::kUndocked;
  if (in.displaced && docking && !pressing_ && !recovering_) {
    recovering_ = true;
    settled_s_ = unsettled_s_ = 0;
  }
  if (recovering_) return recover(in);
  // Re-anchor the dock in the odometry frame: robot pose composed with the detection.
  if (in.charger_in_robot && dock_.placed())
    dock_.update(geom::compose(in.odom_pose, *in.charger_in_robot));
  DockingCommand out = decide(in);
  // The bumper overrides every phase: never push on into what it touches.
  if ((in.bumper_front && out.twist.v_mps > 0) || (in.bumper_rear && out.twist.v_mps < 0))
    out.twist.v_mps = 0;
  return out;
}

Pose2 DockingController::dock_in_map(const DockingInput& in) const {
  return geom::compose(geom::compose(in.pose, geom::inverse(in.odom_pose)), dock_.pose());
}

Vec2 DockingController::charger_in_map(const DockingInput& in) const {
  // What is sensed there is the charger (a charger off its mapped pose returns off the map),
  // not a hazard.
  const Pose2 dock = dock_in_map(in);
  return dock.position() + (params_.guard.footprint_radius_m + 0.05) * dock.heading();
}

bool DockingController::guard(const DockingInput& in, const Twist& twist, bool spare_charger) {
  if (!spare_charger) return guard_.clear(in.pose, in.speed_mps, twist, in.nearby_obstacles);
  std::vector<MovingBox> boxes;
  boxes.reserve(in.nearby_obstacles.size());
  const Vec2 charger_at = charger_in_map(in);
  for (const MovingBox& b : in.nearby_obstacles)
    if (distance_to_box(charger_at, b.box) > 0.25) boxes.push_back(b);
  return guard_.clear(in.pose, in.speed_mps, twist, boxes);
}

bool DockingController::reverse_to_staging(const DockingInput& in, DockingCommand& out) {
  const Vec2 rel = in_dock_frame(in.odom_pose.position());
  if (rel.x <= -params_.staging_distance_m) return true;
  // Reverse straight out, holding the axis heading; the next approach corrects offsets.
  const double heading_err = geom::wrap_angle(dock_.pose().yaw - in.odom_pose.yaw);
  out.twist = {-params_.backoff_speed_mps, std::clamp(1.5 * heading_err, -0.5, 0.5)};
  if (!guard(in, out.twist, false)) {
    // Something behind: wait for it; stopped for good (failed) if it never goes.
    out.twist = {};
    out.blocked = true;
    stuck_time_s_ += in.dt_s;
    if (stuck_time_s_ > params_.stuck_timeout_s)
      fail(phase_ == DockPhase::kUndock ? DockFailure::kUndockBlocked : DockFailure::kBlocked);
  } else {
    stuck_time_s_ = 0;
    guard_.note_clear(in.dt_s);
  }
  return false;
}

DockingCommand DockingController::travel(const DockingInput& in) {
  DockingCommand out;
  const FollowStep f = follower_.step(in, guard_, params_.yield);
  out.twist = f.twist;
  out.cross_track_error_m = f.cross_track_error_m;
  out.blocked = f.blocked;
  out.replan_requested = f.replan_requested;
  if (f.goal_reached) {
    // At the staging pose the map's charger is placed in the odometry frame, once.
    dock_.place(geom::compose(geom::compose(in.odom_pose, geom::inverse(in.pose)), dock_map_));
    phase_ = DockPhase::kAlign;
    out.twist = {};
  }
  return out;
}

DockingCommand DockingController::align(const DockingInput& in) {
  DockingCommand out;
  if (yield(in, out)) return out;  // someone walking at the robot while it turns: out of the way
  const double err = geom::wrap_angle(dock_.pose().yaw - in.odom_pose.yaw);
  if (std::fabs(err) <= params_.align_tolerance_rad) {
    if (bystander_waited_s_ < params_.yield.bystander_wait_s &&
        bystander_near_corridor(params_.yield, in.pose.position(), dock_in_map(in).position(),
                                charger_in_map(in), guard_.radius_m(), in.nearby_obstacles)) {
      bystander_waited_s_ += in.dt_s;
      guard_.note_blocked();
      out.blocked = true;
      return out;
    }
    phase_ = DockPhase::kApproach;
    approach_time_s_ = 0;
  } else {
    out.twist = {0.0, std::clamp(2.0 * err, -params_.align_speed_radps, params_.align_speed_radps)};
  }
  return out;
}

DockingCommand DockingController::decide(const DockingInput& in) {
  DockingCommand out;
  switch (phase_) {
    case DockPhase::kTravel:
      out = travel(in);
      break;
    case DockPhase::kAlign:
      out = align(in);
      break;
    case DockPhase::kApproach:
      out = approach(in);
      break;
    case DockPhase::kBackOff:
      if (reverse_to_staging(in, out)) {
        if (giving_up_)
          fail(DockFailure::kRetriesExhausted);
        else
          phase_ = DockPhase::kAlign;
      }
      break;
    case DockPhase::kUndock:
      if (reverse_to_staging(in, out)) phase_ = DockPhase::kUndocked;
      break;
    case DockPhase::kDocked:
    case DockPhase::kUndocked:
    case DockPhase::kFailed:
      break;
  }
  out.phase = phase_;
  return out;
}

DockingCommand DockingController::approach(const DockingInput& in) {
  DockingCommand out;
  if (in.charging) {
    phase_ = params_.undock ? DockPhase::kUndock : DockPhase::kDocked;
    pressing_ = false;
    stuck_time_s_ = 0;
    return out;
  }
  if (in.charger_contact || pressing_) {
    // The pads touch: hold them pressed, square to the charger, until it reports charging.
    if (!pressing_) press_time_s_ = 0;
    pressing_ = true;
    press_time_s_ += in.dt_s;
    if (press_time_s_ > params_.press_timeout_s) {
      pressing_ = false;
      miss();
      return out;
    }
    out.twist = {params_.press_speed_mps, 0.0};
    return out;
  }
  if (in.bumper_front) {
    // Touched something that is not the pads (the charger's side, an obstacle): back off.
    miss();
    return out;
  }
  const Vec2 rel = in_dock_frame(in.odom_pose.position());
  approach_time_s_ += in.dt_s;
  if (rel.x > params_.overshoot_limit_m || approach_time_s_ > params_.approach_timeout_s) {
    miss();
    return out;
  }
  // Pure pursuit onto the approach axis; the carrot may lie beyond the dock point (inside
  // the charger), which keeps the steering gentle right up to contact.
  const Vec2 carrot_dock{rel.x + params_.approach_lookahead_m, 0.0};
  const Vec2 carrot = dock_.pose().position() + geom::rotate(carrot_dock, dock_.pose().yaw);
  const Vec2 c = to_robot_frame(in.odom_pose, carrot);
  const double d2 = geom::dot(c, c);
  const double curvature = 2.0 * c.y / d2;
  const double v = params_.approach_speed_mps;
  out.twist = {v, v * curvature};
  if (yield(in, out)) return out;  // someone walking into the approach: out of their way
  if (!guard(in, out.twist, true)) {
    // Something between the robot and the charger: wait (the approach clock runs on).
    out.twist = {};
    out.blocked = true;
  } else {
    guard_.note_clear(in.dt_s);
  }
  return out;
}

}  // namespace plantsim::controller
