// Replanning around a few added obstacles (what the robot sensed) without rebuilding the map's
// visibility graph. An added rectangle can only block an edge, never open one, so the map's
// graph stays valid: its vertices, its lazily found candidate edges and their cached
// visibility verdicts are reused as they are, each base edge the search meets is tested
// against the added rectangles only, and the added rectangles' corners join the search as
// extra vertices (edges to the map's vertices come from the same tangent ring scan the start
// uses). The path is exact among the map's and the added obstacles: the convex corners of
// their union are corners of map rectangles (already vertices) or of added ones.
#pragma once

#include <vector>

#include "planner/vg/vg_planner.h"

namespace plantsim::planner {

struct OverlayStats {
  std::int64_t base_candidates = 0;  ///< the map graph's candidate edges the search looked at
  std::int64_t added_tests = 0;      ///< segment tests against the added rectangles
};

/// Exact shortest path from start to goal around `base`'s obstacles and `added` (inflated as
/// the base's are). A start inside an added rectangle (the robot stopped within the clearance
/// of what it sensed) moves to the nearest point outside them, and the result says so; a
/// start or goal blocked on the map, or a goal inside an added rectangle, is kStartBlocked /
/// kGoalBlocked. `base` is only read through its lazily filled caches (not thread-safe).
PlanResult plan_with_added(const VisibilityGraphPlanner& base, const std::vector<Rect>& added,
                           Vec2 start, Vec2 goal, OverlayStats* stats = nullptr);

}  // namespace plantsim::planner
