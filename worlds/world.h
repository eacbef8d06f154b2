// The plant as plantsim sees it: floor bounds, static obstacles as axis-aligned rectangles,
// the robot's specification, its start pose and the charger's docked pose. Pure data plus
// derived geometry (the charger's body and staging pose); loading lives in world_loader.h.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/vec2.h"
#include "worlds/tunnel_maze.h"

namespace plantsim::worlds {

using geom::Pose2;
using geom::Rect;
using geom::Vec2;

/// The inflation of the plain benchmark worlds' optimal lengths (shared/data/README.md): worlds
/// made in that style give robot radius + margin this total.
inline constexpr double kBenchmarkInflation_m = 0.3;

/// Differential-drive robot with a disk or a rectangular footprint. Typical values are those
/// of a small indoor inspection robot.
struct RobotSpec {
  double radius_m = 0.2;         ///< disk radius; for a rectangle, its circumscribed radius
  double wheel_base_m = 0.34;    ///< distance between the two wheel contact points
  double wheel_radius_m = 0.06;  ///< drive wheel radius
  double max_speed_mps = 0.8;    ///< wheel rim speed limit
  double max_accel_mps2 = 1.0;   ///< wheel rim acceleration limit
  double mass_kg = 30.0;         ///< body mass; inertia that of the uniform footprint
  double length_m = 0.0;         ///< rectangular footprint along the heading (0: a disk)
  double width_m = 0.0;          ///< rectangular footprint across the heading

  bool rectangular() const { return length_m > 0 && width_m > 0; }
  /// Distance from the centre to the front, where the charging contacts are.
  double front_extent_m() const { return rectangular() ? 0.5 * length_m : radius_m; }
};

/// The charger's physical body: a block the robot's front touches when docked.
struct ChargerSpec {
  double width_m = 0.30;            ///< across the approach axis
  double depth_m = 0.10;            ///< along the approach axis
  double staging_distance_m = 1.0;  ///< staging pose this far behind the docked pose
  double pad_travel_m = 0.005;  ///< spring travel of the contact pads: the rigid face is half of
                                ///< it past the docked pose, the pads' rest face half of it before
};

/// A box moving on a scripted path at constant speed (a person, a cart, a vehicle): it waits
/// at its first waypoint until start_time_s, then follows the waypoints; with `loop` it goes
/// back and forth forever, otherwise it stays (parks) at the last one. A blind actor (the
/// default) never gives way; one that `yields_to_robot` pauses its script while the robot is
/// in its way, as people and drivers do. Positions are given for the script's own time.
struct MovingObstacle {
  std::string name;
  double width_m = 0.5;
  double height_m = 0.5;
  std::vector<Vec2> waypoints;  ///< positions of the box centre
  double speed_mps = 0.0;
  double start_time_s = 0.0;
  bool loop = false;
  bool yields_to_robot = false;
  double yield_distance_m = 1.5;  ///< gap ahead it keeps to the robot when yielding

  Vec2 position_at(double t_s) const;
  Rect box_at(double t_s) const;
};

struct World {
  std::string name;             ///< short name for reports
  std::string source;           ///< file it was loaded from, for messages
  Rect floor;                   ///< the floor; its boundary is a wall
  std::vector<Rect> obstacles;  ///< static obstacles, closed rectangles
  RobotSpec robot;
  ChargerSpec charger_spec;
  Pose2 start;                         ///< robot start pose
  Pose2 charger;                       ///< robot pose when docked (yaw faces the charger)
  double inflation_margin_m = 0.1;     ///< planning clearance beyond the robot radius
  std::vector<MovingObstacle> moving;  ///< not known to the planner; met on the way
  /// Static obstacles in the plant but not on the robot's map (a pallet left in an aisle): the
  /// physics and the sensors have them; the planner, the localiser and the controllers only
  /// know them if perception senses them.
  std::vector<Rect> unmapped;
  /// The charger's pose on the robot's map minus its real pose (`charger` is where it really
  /// stands; a charger re-bolted off its drawing has a non-zero offset). World frame, m and rad.
  Pose2 charger_map_offset{0.0, 0.0, 0.0};
  /// A moving target to catch (seed 001's pursuit): with one, an episode succeeds when the
  /// robot reaches it, and the charger is not used. It does not collide with anything.
  std::optional<MovingObstacle> target;
  /// Seed 003's tunnel lattice, when the world is a cable-tunnel maze (floor and obstacles
  /// are then derived from it).
  std::optional<TunnelMaze> maze;

  /// Total inflation the planner applies to obstacles and walls.
  double planning_inflation_m() const { return robot.radius_m + inflation_margin_m; }
};

/// True when the robot's map differs from the plant (unmapped obstacles, a shifted charger).
bool differs_from_map(const World& plant);

/// The docked pose as the robot's map has it (the charger plus its map offset).
Pose2 robot_map_charger(const World& plant);

/// The plant as the robot's map has it: no unmapped obstacles, the charger where the map says.
World robot_map(const World& plant);

/// The charger block in world coordinates as an oriented box: centre, half extents, yaw.
struct ChargerBody {
  Vec2 center;
  double half_depth_m;
  double half_width_m;
  double yaw;
  Rect bounding_box() const;
};

/// The block sits just ahead of the docked pose, its face at robot radius from the centre.
ChargerBody charger_body(const World& world);
/// The same block for the docked pose `docked` (the map's, say, instead of the real one).
ChargerBody charger_body(const World& world, const Pose2& docked);

/// Where the final approach starts: on the approach axis, staging_distance behind docked.
Pose2 staging_pose(const World& world);

}  // namespace plantsim::worlds
