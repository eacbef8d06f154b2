// ROS map_server maps (YAML + PGM or PNG) as plantsim worlds. Occupancy follows map_server
// (Nav2's map_io): a pixel's shade s runs from 0 (black) to 1 (white) over its samples' full
// scale (8 or 16 bits, a PGM's maximum), colours averaged; its probability is 1 - s (s when
// negate is set); above occupied_thresh it is occupied, below free_thresh free, otherwise
// unknown ("trinary" and "scale" modes); "raw" mode reads round(255 s) as a percentage. Alpha:
// in trinary mode averaged in as a fourth channel (a transparent white pixel is unknown at the
// usual thresholds), in scale and raw modes a pixel not fully opaque is unknown. Unknown
// counts as blocked: a robot must not plan through what it has never seen. Blocked pixels are
// merged into few rectangles.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "worlds/grid_map.h"
#include "worlds/world.h"

namespace plantsim::worlds {

struct RosMap {
  GridMap grid;             ///< '@' blocked (occupied or unknown), '.' free; row 0 at the top
  double resolution_m = 0;  ///< metres per pixel
  Vec2 origin;              ///< world position of the bottom-left pixel's corner
  std::size_t occupied = 0, unknown = 0, free = 0;  ///< pixel counts
};

/// Throws WorldError naming the YAML or PGM file and the field at fault.
RosMap load_ros_map(const std::string& yaml_path);

/// A world from a ROS map: the map's blocked pixels as merged rectangles, the floor the map's
/// extent. Start and charger come from the caller, or are placed automatically: the charger
/// against a wall (facing it, with room to dock) in the largest free region, or, where no
/// straight wall has room, free-standing at the most open spot; the start at the free point
/// of the same region farthest from it.
World world_from_ros_map(const RosMap& map, const std::string& name, std::optional<Pose2> start,
                         std::optional<Pose2> charger);

/// Places the charger against a wall of `world` (obstacles already set); none if no room.
/// `staging_ok`, when given, must accept the candidate's staging position.
std::optional<Pose2> place_charger_against_wall(const World& world,
                                                const std::function<bool(Vec2)>& staging_ok = {});

}  // namespace plantsim::worlds
