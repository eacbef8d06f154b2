// Reading worlds from files: plantsim's world JSON (schema in docs/world_format.md) and the
// plain benchmark worlds of shared/data/worlds (rects/start/goal; the goal becomes the
// charger). Every problem is reported as a WorldError naming the file and the field.
#pragma once

#include <optional>
#include <string>

#include "worlds/world.h"
#include "worlds/world_error.h"

namespace plantsim::worlds {

/// Poses the user gives on the command line; for a ROS map they replace automatic placement.
struct PoseOverrides {
  std::optional<Pose2> start;
  std::optional<Pose2> charger;
  std::string movingai_scen;  ///< for a MovingAI .map: the .scen whose query gives start and goal
  int movingai_query = 0;     ///< that query's number, from 0
};

/// Loads and validates a world file: plantsim JSON, a plain benchmark world, a ROS map_server
/// YAML (.yaml/.yml) or a MovingAI map (.map, with a .scen query or both poses). "$data/..."
/// is under the shared data folder. Throws WorldError on any problem.
World load_world(const std::string& path, const PoseOverrides& overrides = {});

/// Parses and validates world JSON text; `source` names it in messages.
World parse_world_json(const std::string& text, const std::string& source);

/// Throws WorldError (naming `field`) unless the robot's footprint at `pose` lies inside the
/// floor and clear of every obstacle.
void check_pose_free(const World& world, const Pose2& pose, const std::string& field);

/// Checks a world for consistency (finite numbers, positive sizes, robot fits, start and
/// charger free of obstacles and inside the floor). Throws WorldError.
void validate_world(const World& world);

}  // namespace plantsim::worlds
