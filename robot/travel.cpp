// The helpers every travel mode shares: replanning around what is sensed, and the docking
// controller's input.
#include "robot/travel.h"

#include <algorithm>
#include <stdexcept>

#include "controller/pure_pursuit_controller.h"
#include "planner/planner.h"
#include "planner/registry.h"

namespace plantsim::robot {

namespace {

double sensed_extra_m(const worlds::World& map, const controller::DockingParams& docking) {
  return std::max(0.0, docking.guard.safety_margin_m - map.inflation_margin_m) + 0.05;
}

}  // namespace

std::vector<geom::Rect> sensed_blocks(const worlds::World& map,
                                      const controller::DockingParams& docking,
                                      const std::vector<controller::MovingBox>& seen) {
  const double grow = sensed_extra_m(map, docking) + map.planning_inflation_m();
  std::vector<geom::Rect> added;
  added.reserve(seen.size());
  for (const auto& b : seen) added.push_back(b.box.inflated(grow));
  return added;
}

std::optional<std::vector<geom::Vec2>> plan_around(const worlds::World& map,
                                                   const std::string& planner_name,
                                                   const controller::DockingParams& docking,
                                                   const geom::Pose2& from, geom::Vec2 to,
                                                   const std::vector<controller::MovingBox>& seen,
                                                   const planner::Planner* map_planner) {
  const double extra = sensed_extra_m(map, docking);
  const std::vector<geom::Rect> added = sensed_blocks(map, docking, seen);
  const std::optional<planner::PlanResult> around =
      map_planner ? map_planner->plan_around_added(added, from.position(), to) : std::nullopt;
  if (around) {
    const planner::PlanResult& re = *around;
    if (re.status == planner::PlanStatus::kOk) {
      std::vector<geom::Vec2> path = re.path;
      if (re.start_snapped) path.insert(path.begin(), from.position());
      return path;
    }
    // No path, or a search past its budget (a rebuild would search as far): no replan.
    if (re.status != planner::PlanStatus::kStartBlocked &&
        re.status != planner::PlanStatus::kGoalBlocked)
      return std::nullopt;
    // Start or goal blocked on the map itself (shoved into a margin): the rebuild snaps them.
  }
  planner::PlannerInput again = planner::planner_input(map, true);
  for (const auto& b : seen) again.obstacles.push_back(b.box.inflated(extra));
  again.snap_to_free = true;
  const planner::PlanResult re =
      planner::make_planner(planner_name, again)->plan(from.position(), to);
  if (re.status != planner::PlanStatus::kOk) return std::nullopt;
  std::vector<geom::Vec2> path = re.drive_path.empty() ? re.path : re.drive_path;
  if (re.start_snapped) path.insert(path.begin(), from.position());
  return path;
}

std::unique_ptr<controller::LocalController> make_local_controller(const TravelSettings& s) {
  if (!s.local) return controller::make_pure_pursuit(s.tracking);
  std::unique_ptr<controller::LocalController> made =
      s.local->make(s.local_context, s.local_params);
  if (!made)
    throw std::runtime_error("local controller \"" + s.local->name + "\" (" + s.local->origin +
                             ") made nothing");
  return made;
}

controller::DockingInput docking_input(const Perception& p) {
  controller::DockingInput in;
  in.pose = p.pose;
  in.odom_pose = p.odom_pose;
  in.speed_mps = p.speed_mps;
  in.yaw_rate_radps = p.yaw_rate_radps;
  in.dt_s = p.dt_s;
  in.charger_contact = p.charger_contact;
  in.charging = p.charging;
  in.charger_in_robot = p.charger_in_robot;
  in.nearby_obstacles = p.obstacles;
  in.bumper_front = p.bumper.front;
  in.bumper_rear = p.bumper.rear;
  in.displaced = p.displaced;
  // Settled enough to plan a new way from: not lost, and tight enough to keep its margins.
  in.localized = p.health != LocalizationHealth::kLost && p.position_sigma_m <= 0.15;
  in.position_sigma_m = p.position_sigma_m;
  return in;
}

namespace {

FailureReason reason_of(controller::DockFailure why) {
  using controller::DockFailure;
  switch (why) {
    case DockFailure::kRetriesExhausted:
      return FailureReason::kDockRetriesExhausted;
    case DockFailure::kBlocked:
      return FailureReason::kBlocked;
    case DockFailure::kUnsettled:
      return FailureReason::kStuck;
    case DockFailure::kNotLocalized:
      return FailureReason::kLocalizationLost;
    case DockFailure::kUndockBlocked:
      return FailureReason::kUndockFailed;
    case DockFailure::kNone:
      break;
  }
  return FailureReason::kStuck;
}

}  // namespace

Decision decision_of(const controller::DockingCommand& cmd, controller::DockFailure why) {
  Decision d{cmd.twist,    cmd.phase, cmd.cross_track_error_m, false, TravelEnd::kNone, cmd.blocked,
             std::nullopt, cmd.events};
  if (cmd.phase == controller::DockPhase::kDocked) d.finished = TravelEnd::kDocked;
  if (cmd.phase == controller::DockPhase::kUndocked) d.finished = TravelEnd::kUndocked;
  if (cmd.phase == controller::DockPhase::kFailed) {
    d.finished = TravelEnd::kFailed;
    d.give_up = GiveUp{reason_of(why),
                       "the docking controller: " + std::string(controller::to_string(why))};
  }
  return d;
}

}  // namespace plantsim::robot
