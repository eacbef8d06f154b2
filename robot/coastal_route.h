// Coastal navigation (Roy and Thrun's term): the route the robot drives when the shortest path
// would cross a long stretch of open ground with no mapped surface within its lidar's sight.
// There a scan matches nothing, the estimate follows odometry and the gyro, and the gyro's bias
// turns a heading error into metres: on a 160 x 90 m yard the shortest path left robots 10 to
// 17 m off. The coastal route trades length for sight: it keeps mapped surfaces (the map's boxes,
// the charger, the floor's walls) within sight where it can, and crosses open ground where the
// crossing is short. It reads the map and the lidar's datasheet range only.
#pragma once

#include <vector>

#include "geometry/vec2.h"
#include "worlds/world.h"

namespace plantsim::robot {

struct CoastalParams {
  bool enabled = true;
  /// A point is in sight of a surface within this fraction of the lidar's range (a surface near
  /// the range's end gives few, grazing returns).
  double sight_fraction = 0.6;
  /// The shortest path is driven unless one of its blind stretches (no surface in sight) is
  /// longer than this.
  double activate_blind_m = 15.0;
  /// A blind stretch of length L costs L^2 / this, on top of its length: the error a heading
  /// error leaves grows faster than the distance driven blind.
  double blind_scale_m = 10.0;
  double node_spacing_m = 5.0;  ///< the route's candidate turns along the edge of sight
  int max_nodes = 1500;         ///< more candidates than this (a crowded map): the shortest path
};

/// What a route's blind stretches amount to.
struct Blindness {
  double longest_m = 0;  ///< the longest stretch with no surface in sight
  double total_m = 0;
  double cost_m = 0;  ///< the sum of L^2 / blind_scale_m
};

/// The blind stretches of a polyline on `map` with a lidar of range `lidar_range_m`.
Blindness blindness(const worlds::World& map, const std::vector<geom::Vec2>& path,
                    double lidar_range_m, const CoastalParams& params);

/// The route from path.front() to path.back(): `path` itself unless it has a blind stretch
/// longer than activate_blind_m, else the route of least length plus blind cost over the map's
/// free space (its obstacles grown as the planner grows them, and `blocked`, already grown, for
/// what the robot has sensed), when that costs less than `path`.
std::vector<geom::Vec2> coastal_route(const worlds::World& map, std::vector<geom::Vec2> path,
                                      double lidar_range_m, const CoastalParams& params,
                                      const std::vector<geom::Rect>& blocked = {});

}  // namespace plantsim::robot
