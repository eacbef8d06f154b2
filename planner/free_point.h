// The nearest point a path may start or end at, for a point inside an inflated obstacle or
// off the floor. The boundary of the obstacle union is made of axis-parallel pieces whose
// coordinates come from the rectangles, so the nearest free point has each coordinate either
// equal to the query's or taken from a nearby rectangle: candidates are built from those
// exact coordinates and checked with the exact point test, within a search radius that
// doubles until one is found.
#pragma once

#include <optional>

#include "planner/obstacle_map.h"
#include "planner/planner.h"

namespace plantsim::planner {

/// p itself when it is free; none when no free point lies within the map.
std::optional<Vec2> nearest_free_point(const ObstacleMap& map, Vec2 p);

/// A query's ends checked before a search: false (with `out.status` set) when one is blocked
/// and may not move; with `snap`, a blocked end moves to its nearest free point and `out` says so.
bool usable_endpoints(const ObstacleMap& map, bool snap, Vec2& start, Vec2& goal, PlanResult& out);

}  // namespace plantsim::planner
