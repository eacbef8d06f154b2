// The nearest point a path may start or end at, for a point inside an inflated obstacle or
// off the floor. The boundary of the obstacle union is made of axis-parallel pieces whose
// coordinates come from the rectangles, so the nearest free point has each coordinate either
// equal to the query's or taken from a nearby rectangle: candidates are built from those
// exact coordinates and checked with the exact point test, within a search radius that
// doubles until one is found.
#pragma once

#include <optional>

#include "planner/obstacle_map.h"

namespace plantsim::planner {

/// p itself when it is free; none when no free point lies within the map.
std::optional<Vec2> nearest_free_point(const ObstacleMap& map, Vec2 p);

}  // namespace plantsim::planner
