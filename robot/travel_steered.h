// A controller from outside plantsim (a user's own, through the Python module) steering in place
// of path following, and, if given one, of the docking manoeuvre. plantsim's own travel keeps
// running beside it and stays the referee: it keeps the plan (replanning around what the robot
// senses), notices the staging pose and hands over to docking, and judges docked or failed by
// the same rules as for its own controller. The outside controller sees only the perception.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "robot/travel.h"

namespace plantsim::robot {

/// What an outside controller is given each control period.
struct SteeringInput {
  const Perception& perception;
  const std::vector<geom::Vec2>& plan;  ///< the plan plantsim's travel holds now (after replans)
  controller::DockPhase phase;  ///< plantsim's phase: travel until the staging pose is reached
  const Decision& builtin;      ///< what plantsim's own controller would command now
  geom::Pose2 staging;          ///< the staging pose on the map, where docking takes over
};

/// A twist to drive with, or nothing to let plantsim's own controller command this period.
using Steering = std::function<std::optional<controller::Twist>(const SteeringInput&)>;

/// `builtin`, steered by `travel` while its phase is travel and by `docking` (if set) after.
std::unique_ptr<Travel> steered_by(std::unique_ptr<Travel> builtin, const worlds::World& map,
                                   std::vector<geom::Vec2> first_plan, Steering travel,
                                   Steering docking = {});

}  // namespace plantsim::robot
