// Docking state machine.
#include "controller/docking.h"

#include <algorithm>
#include <cmath>

#include "controller/collision_check.h"

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

double uncertainty_speed_fraction(const DockingParams& p, double position_sigma_m) {
  if (!(position_sigma_m > p.confident_sigma_m)) return 1.0;
  if (!(p.uncertain_sigma_m > p.confident_sigma_m) || position_sigma_m >= p.uncertain_sigma_m)
    return p.uncertain_speed_fraction;
  const double share =
      (position_sigma_m - p.confident_sigma_m) / (p.uncertain_sigma_m - p.confident_sigma_m);
  return 1.0 - share * (1.0 - p.uncertain_speed_fraction);
}

void DockingController::fail(DockFailure why) {
  phase_ = DockPhase::kFailed;
  failure_ = why;
}

DockingController::DockingController(PurePursuitParams tracking, DockingParams docking,
                                     std::vector<Vec2> path, Pose2 charger_on_map)
    : tracker_(tracking, std::move(path)),
      params_(docking),
      dock_map_(charger_on_map),
      dock_odom_(charger_on_map) {}

Vec2 DockingController::in_dock_frame(Vec2 p) const { return to_robot_frame(dock_odom_, p); }

void DockingController::replace_path(std::vector<Vec2> path) {
  if (phase_ == DockPhase::kTravel) tracker_ = PurePursuit(tracker_.params(), std::move(path));
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

void DockingController::use_detection(const Pose2& seen) {
  // A detection far from the estimate is an outlier unless the next one confirms it (a map
  // placement that was off is corrected by two agreeing detections).
  auto near = [&](const Pose2& a, const Pose2& b) {
    return geom::distance(a.position(), b.position()) <= params_.detection_gate_m &&
           std::fabs(geom::wrap_angle(a.yaw - b.yaw)) <=
               params_.detection_gate_m / params_.staging_distance_m;
  };
  if (!near(seen, dock_odom_)) {
    const bool confirmed = rejected_detection_ && near(seen, *rejected_detection_);
    rejected_detection_ = seen;
    if (!confirmed) return;
  }
  rejected_detection_.reset();
  const double a = params_.detection_blend;
  dock_odom_.x += a * (seen.x - dock_odom_.x);
  dock_odom_.y += a * (seen.y - dock_odom_.y);
  dock_odom_.yaw =
      geom::wrap_angle(dock_odom_.yaw + a * geom::wrap_angle(seen.yaw - dock_odom_.yaw));
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
    dock_placed_ = false;
    pressing_ = false;
    rejected_detection_.reset();
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
  std::vector<MovingBox> movers;
  for (const MovingBox& b : in.nearby_obstacles)
    if (geom::norm(b.velocity) > 0.2) movers.push_back(b);
  if (movers.empty() ||
      !position_threatened(in.pose.position(),
                           params_.footprint_radius_m + 0.5 * params_.safety_margin_m, movers,
                           params_.yield_horizon_s))
    return false;
  const Twist back{-params_.yield_speed_mps, 0.0};
  out.twist = guard(in, back, false) ? back : Twist{};
  out.blocked = true;
  return true;
}

DockingCommand DockingController::step(const DockingInput& in) {
  events_ = {};
  DockingCommand out = step_phase(in);
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
  if (in.charger_in_robot && dock_placed_)
    use_detection(geom::compose(in.odom_pose, *in.charger_in_robot));
  DockingCommand out = decide(in);
  // The bumper overrides every phase: never push on into what it touches.
  if ((in.bumper_front && out.twist.v_mps > 0) || (in.bumper_rear && out.twist.v_mps < 0))
    out.twist.v_mps = 0;
  return out;
}

Vec2 DockingController::charger_in_map(const DockingInput& in) const {
  // What is sensed there is the charger (a charger off its mapped pose returns off the map),
  // not a hazard.
  const Pose2 dock_in_map =
      geom::compose(geom::compose(in.pose, geom::inverse(in.odom_pose)), dock_odom_);
  return dock_in_map.position() + (params_.footprint_radius_m + 0.05) * dock_in_map.heading();
}

bool DockingController::bystander_near_approach(const DockingInput& in) const {
  const Pose2 dock_in_map =
      geom::compose(geom::compose(in.pose, geom::inverse(in.odom_pose)), dock_odom_);
  const Vec2 charger_at = charger_in_map(in);
  const double near =
      params_.footprint_radius_m + params_.safety_margin_m + params_.bystander_reach_m;
  for (const MovingBox& b : in.nearby_obstacles) {
    if (distance_to_box(charger_at, b.box) <= 0.25) continue;
    if (std::max(b.box.width(), b.box.height()) > params_.bystander_max_size_m) continue;
    if (segment_distance_to_box(in.pose.position(), dock_in_map.position(), b.box) < near)
      return true;
  }
  return false;
}

bool DockingController::guard(const DockingInput& in, const Twist& twist, bool spare_charger) {
  std::vector<MovingBox> boxes;
  boxes.reserve(in.nearby_obstacles.size());
  const Vec2 charger_at = charger_in_map(in);
  for (const MovingBox& b : in.nearby_obstacles)
    if (!spare_charger || distance_to_box(charger_at, b.box) > 0.25) boxes.push_back(b);
  const double v = std::max(std::fabs(twist.v_mps), std::fabs(in.speed_mps));
  const double ahead = v * v / (2.0 * params_.max_decel_mps2) + params_.check_extra_m;
  if (arc_clear(in.pose, twist, std::max(v, 0.1), ahead,
                params_.footprint_radius_m + params_.safety_margin_m, boxes))
    return true;
  note_blocked();
  return false;
}

bool DockingController::reverse_to_staging(const DockingInput& in, DockingCommand& out) {
  const Vec2 rel = in_dock_frame(in.odom_pose.position());
  if (rel.x <= -params_.staging_distance_m) return true;
  // Reverse straight out, holding the axis heading; the next approach corrects offsets.
  const double heading_err = geom::wrap_angle(dock_odom_.yaw - in.odom_pose.yaw);
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
    note_clear(in.dt_s);
  }
  return false;
}

void DockingController::note_blocked() {
  if (!was_blocked_ && clear_time_s_ >= 1.0) {
    ++stops_;
    events_.stopped = true;
  }
  was_blocked_ = true;
  clear_time_s_ = 0;
}

void DockingController::note_clear(double dt_s) {
  was_blocked_ = false;
  clear_time_s_ += dt_s;
}

DockingCommand DockingController::travel(const DockingInput& in) {
  DockingCommand out;
  TrackingCommand t = tracker_.step(in.pose, in.speed_mps);
  // Slower when unsure where it is: the same arc, at a share of the speed.
  const double slow = uncertainty_speed_fraction(params_, in.position_sigma_m);
  t.twist = {slow * t.twist.v_mps, slow * t.twist.omega_radps};
  out.cross_track_error_m = t.cross_track_error_m;
  out.twist = t.twist;
  // Stop short of anything moving into the arc ahead; ask for a replan if it stays.
  const double v = std::max(std::fabs(t.twist.v_mps), std::fabs(in.speed_mps));
  // Never beyond the corner where it will stop and turn in place: a straight arc past it
  // would clip what the path itself turns away from.
  const double braking = v * v / (2.0 * params_.max_decel_mps2);
  const double ahead =
      std::min(braking + params_.check_extra_m, std::max(braking, t.straight_ahead_m) + 0.05);
  // Slow (starting or slowing) robots take longer to get there: never assume less than
  // a walking pace's worth of time for the obstacles to move.
  const double travel_speed =
      std::max(0.5 * (std::fabs(in.speed_mps) + std::fabs(t.twist.v_mps)), 0.1);
  if (!arc_clear(in.pose, t.twist, travel_speed, ahead,
                 params_.footprint_radius_m + params_.safety_margin_m, in.nearby_obstacles)) {
    hold_blocked(in, t, out);
    return out;
  }
  blocked_time_s_ = 0;
  was_blocked_ = false;
  clear_time_s_ += in.dt_s;
  if (std::fabs(t.twist.omega_radps) < 0.05)
    straight_run_m_ += t.twist.v_mps * in.dt_s;
  else
    straight_run_m_ = 0;
  if (t.goal_reached) {
    // At the staging pose the map's charger is placed in the odometry frame, once.
    dock_odom_ = geom::compose(geom::compose(in.odom_pose, geom::inverse(in.pose)), dock_map_);
    phase_ = DockPhase::kAlign;
    dock_placed_ = true;
    out.twist = {};
  }
  return out;
}

void DockingController::hold_blocked(const DockingInput& in, const TrackingCommand& t,
                                     DockingCommand& out) {
  // One stop per encounter: a tracked obstacle's estimated velocity wobbles, and the arc
  // check with it; a go of less than a second between two blocks is the same stop.
  note_blocked();
  out.twist = {};
  out.blocked = true;
  // Stopped in something's way (it does not yield): back out along the stretch just driven.
  const bool threatened = position_threatened(
      in.pose.position(), params_.footprint_radius_m + 0.5 * params_.safety_margin_m,
      in.nearby_obstacles, params_.yield_horizon_s);
  const Twist back{-params_.yield_speed_mps, 0.0};
  if (straight_run_m_ > 0.05 && threatened && guard(in, back, false)) {
    // ... only while what it senses leaves that stretch clear (a person may be behind too).
    out.twist = back;
    straight_run_m_ -= params_.yield_speed_mps * in.dt_s;
  } else if (!threatened && std::fabs(t.carrot_bearing_rad) > params_.align_tolerance_rad) {
    // Nothing coming: face the carrot in place (a disk turns without sweeping anything),
    // so that the next arc is straight, not one that bulges into what blocked the curve.
    out.twist = {0.0, std::clamp(2.0 * t.carrot_bearing_rad, -params_.align_speed_radps,
                                 params_.align_speed_radps)};
  }
  blocked_time_s_ += in.dt_s;
  if (blocked_time_s_ >= params_.replan_after_s) {
    out.replan_requested = true;
    blocked_time_s_ = 0;
  }
}

DockingCommand DockingController::align(const DockingInput& in) {
  DockingCommand out;
  if (yield(in, out)) return out;  // someone walking at the robot while it turns: out of the way
  const double err = geom::wrap_angle(dock_odom_.yaw - in.odom_pose.yaw);
  if (std::fabs(err) <= params_.align_tolerance_rad) {
    if (bystander_waited_s_ < params_.bystander_wait_s && bystander_near_approach(in)) {
      bystander_waited_s_ += in.dt_s;
      note_blocked();
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
  const Vec2 carrot = dock_odom_.position() + geom::rotate(carrot_dock, dock_odom_.yaw);
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
    note_clear(in.dt_s);
  }
  return out;
}

}  // namespace plantsim::controller
