// Docking state machine.
#include "controller/docking.h"

#include <algorithm>
#include <cmath>

namespace plantsim::controller {

std::string_view to_string(DockPhase p) {
  switch (p) {
    case DockPhase::kTravel: return "travel";
    case DockPhase::kAlign: return "align";
    case DockPhase::kApproach: return "approach";
    case DockPhase::kBackOff: return "back_off";
    case DockPhase::kDocked: return "docked";
    case DockPhase::kFailed: return "failed";
  }
  return "unknown";
}

DockingController::DockingController(PurePursuitParams tracking, DockingParams docking,
                                     std::vector<Vec2> path, Pose2 charger_on_map)
    : tracker_(tracking, std::move(path)), params_(docking), dock_(charger_on_map) {}

Vec2 DockingController::in_dock_frame(Vec2 p) const { return to_robot_frame(dock_, p); }

void DockingController::miss() {
  ++retries_;
  phase_ = retries_ > params_.max_retries ? DockPhase::kFailed : DockPhase::kBackOff;
}

DockingCommand DockingController::step(const DockingInput& in) {
  if (in.charger_in_robot) {
    // Re-anchor the dock in the odometry frame: robot pose composed with the detection.
    const Vec2 offset = geom::rotate(in.charger_in_robot->position(), in.pose.yaw);
    const Pose2 seen{in.pose.x + offset.x, in.pose.y + offset.y,
                     geom::wrap_angle(in.pose.yaw + in.charger_in_robot->yaw)};
    const double a = params_.detection_blend;
    dock_.x += a * (seen.x - dock_.x);
    dock_.y += a * (seen.y - dock_.y);
    dock_.yaw = geom::wrap_angle(dock_.yaw + a * geom::wrap_angle(seen.yaw - dock_.yaw));
  }
  DockingCommand out;
  switch (phase_) {
    case DockPhase::kTravel: {
      const TrackingCommand t = tracker_.step(in.pose, in.speed_mps);
      out.cross_track_error_m = t.cross_track_error_m;
      out.twist = t.twist;
      if (t.goal_reached) {
        phase_ = DockPhase::kAlign;
        out.twist = {};
      }
      break;
    }
    case DockPhase::kAlign: {
      const double err = geom::wrap_angle(dock_.yaw - in.pose.yaw);
      if (std::fabs(err) <= params_.align_tolerance_rad) {
        phase_ = DockPhase::kApproach;
      } else {
        out.twist = {0.0, std::clamp(2.0 * err, -params_.align_speed_radps, params_.align_speed_radps)};
      }
      break;
    }
    case DockPhase::kApproach:
      out = approach(in);
      break;
    case DockPhase::kBackOff: {
      const Vec2 rel = in_dock_frame(in.pose.position());
      if (rel.x <= -params_.staging_distance_m) {
        phase_ = DockPhase::kAlign;
      } else {
        // Reverse straight out, holding the axis heading; the next approach corrects offsets.
        const double heading_err = geom::wrap_angle(dock_.yaw - in.pose.yaw);
        out.twist = {-params_.backoff_speed_mps, std::clamp(1.5 * heading_err, -0.5, 0.5)};
      }
      break;
    }
    case DockPhase::kDocked:
    case DockPhase::kFailed:
      break;
  }
  out.phase = phase_;
  return out;
}

DockingCommand DockingController::approach(const DockingInput& in) {
  DockingCommand out;
  if (in.charger_contact) {
    if (in.charging) {
      phase_ = DockPhase::kDocked;
    } else {
      miss();
    }
    return out;
  }
  const Vec2 rel = in_dock_frame(in.pose.position());
  if (rel.x > params_.overshoot_limit_m) {
    miss();
    return out;
  }
  // Pure pursuit onto the approach axis; the carrot may lie beyond the dock point (inside
  // the charger), which keeps the steering gentle right up to contact.
  const Vec2 carrot_dock{rel.x + params_.approach_lookahead_m, 0.0};
  const Vec2 carrot = dock_.position() + geom::rotate(carrot_dock, dock_.yaw);
  const Vec2 c = to_robot_frame(in.pose, carrot);
  const double d2 = geom::dot(c, c);
  const double curvature = 2.0 * c.y / d2;
  const double v = params_.approach_speed_mps;
  out.twist = {v, v * curvature};
  return out;
}

}  // namespace plantsim::controller
