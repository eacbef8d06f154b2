// The shortest path through a channel: a row of convex polygons, each joined to the next by a
// shared edge (a portal), from a point in the first to a point in the last. Where a channel is
// the only way between two points (every portal a bridge of the mesh, DeadEnds), this is the
// shortest path between them, found without a search by the funnel algorithm (Lee and
// Preparata 1984; as Mononen's "simple stupid funnel"): the path bends only at a portal's end,
// where the funnel of directions still open from the last bend closes over it.
#pragma once

#include <vector>

#include "geometry/vec2.h"

namespace plantsim::planner {

using geom::Vec2;

/// A portal as the path crosses it: its end on the walker's left and on the right.
struct Portal {
  Vec2 left, right;
};

/// start, the bends, goal. `tolerance`: a length; sides closer than it count as on the line.
std::vector<Vec2> funnel_path(Vec2 start, const std::vector<Portal>& portals, Vec2 goal,
                              double tolerance);

}  // namespace plantsim::planner
