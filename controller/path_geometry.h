// Free functions on polylines used by path tracking: closest point with monotone progress,
// the point a given arc length ahead, remaining length, and signed cross-track error.
#pragma once

#include <cstddef>
#include <vector>

#include "geometry/polyline.h"
#include "geometry/vec2.h"

namespace plantsim::controller {

using geom::Pose2;
using geom::Vec2;

struct PathPoint {
  std::size_t segment = 0;  ///< index i of segment [path[i], path[i+1]]
  double t = 0;             ///< fraction along that segment, 0..1
  Vec2 point;
  double distance = 0;  ///< from the query point
};

/// Closest point on the path at or after `from_segment` (progress never goes back), looking
/// at most `window_m` of path ahead so that a path folding back on itself is not skipped.
PathPoint closest_point(const std::vector<Vec2>& path, Vec2 p, std::size_t from_segment,
                        double window_m);

/// Whether the path turns by more than `sharp_turn_rad` at interior vertex `vertex`.
bool sharp_vertex(const std::vector<Vec2>& path, std::size_t vertex, double sharp_turn_rad);

/// The point `ahead_m` further along the path from `from` (clamped to the path's end). The walk
/// stops at the first vertex where the path turns by more than `sharp_turn_rad` when that vertex
/// is more than `corner_release_m` ahead: a carrot beyond a corner pulls the robot across it
/// (and visibility-graph paths bend exactly at obstacle corners).
Vec2 point_ahead(const std::vector<Vec2>& path, const PathPoint& from, double ahead_m,
                 double sharp_turn_rad = M_PI, double corner_release_m = 0.0);

/// Path length from `from` to the next vertex turning by more than `sharp_turn_rad` (or to the
/// end), looking at most `horizon_m` ahead.
double distance_to_sharp_corner(const std::vector<Vec2>& path, const PathPoint& from,
                                double sharp_turn_rad, double horizon_m);

/// For each vertex i, the path length from it to the end (computed once per path).
std::vector<double> lengths_to_end(const std::vector<Vec2>& path);

/// Path length from `from` to the end, given lengths_to_end(path).
double remaining_length(const std::vector<Vec2>& path, const std::vector<double>& to_end,
                        const PathPoint& from);

/// Expresses world point p in the frame of pose (x forward, y left).
Vec2 to_robot_frame(const Pose2& pose, Vec2 p);

}  // namespace plantsim::controller
