// The planner interface's own parts: status names and the World-to-planner adapter.
#include "planner/planner.h"

#include <stdexcept>

namespace plantsim::planner {

std::string_view to_string(PlanStatus s) {
  switch (s) {
    case PlanStatus::kOk:
      return "ok";
    case PlanStatus::kNoPath:
      return "no path";
    case PlanStatus::kStartBlocked:
      return "start blocked";
    case PlanStatus::kGoalBlocked:
      return "goal blocked";
    case PlanStatus::kSearchLimit:
      return "search limit";
  }
  return "unknown";
}

PlannerInput planner_input(const worlds::World& world, bool include_charger_body) {
  PlannerInput in;
  in.floor = world.floor;
  in.obstacles = world.obstacles;  // the map's: unmapped obstacles are the plant's alone
  in.inflation_m = world.planning_inflation_m();
  // The charger where the map has it.
  if (include_charger_body)
    in.obstacles.push_back(
        worlds::charger_body(world, worlds::robot_map_charger(world)).bounding_box());
  in.maze = world.maze;
  return in;
}

}  // namespace plantsim::planner
