// The travel modes by name (`travel` in a configuration, `--travel` on the command line): how
// the robot gets to the staging pose, or to a moving target. The built-ins are "path" (follow
// the planner's path with the chosen local controller; chase a moving target along plans made
// again every period) and "potential-field" (seed 001's field with wall following; the plan is
// only the reference). A new mode is its files and one entry in the .cpp; the episode asks an
// entry's capabilities, never its name.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "robot/travel.h"
#include "util/component_info.h"
#include "util/component_registry.h"

namespace plantsim::robot {

/// The capabilities a travel mode may list.
namespace travel_capability {
/// Travels along the planner's path: without one (no path, start blocked) the episode ends with
/// the planner's answer before it begins.
inline constexpr const char* kNeedsAPlan = "needs-a-plan";
/// Drives at the motors' limit from a standstill, without the soft start (seed 001's robot).
inline constexpr const char* kStartsAtMotorLimit = "starts-at-motor-limit";
}  // namespace travel_capability

/// What a travel mode is built for: the robot's map, the planner's name (for replans), the
/// settings every mode shares and the first plan (or the straight line to the goal when the
/// planner found none).
struct TravelContext {
  const worlds::World* map = nullptr;
  std::string planner_name;
  const TravelSettings* settings = nullptr;
  std::vector<geom::Vec2> first_path;
};

struct TravelEntry : util::ComponentInfo {
  std::function<std::unique_ptr<Travel>(const TravelContext&, const util::ParamValues&)> make;
};

using TravelRegistry = util::ComponentRegistry<TravelEntry>;

/// The registry, the built-ins added on first use.
TravelRegistry& travel_modes();

inline constexpr const char* kDefaultTravel = "path";

}  // namespace plantsim::robot
