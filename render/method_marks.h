// What a method showed of its own working, drawn over a world panel: seed 003's ring-search
// walks (dashed, each shifted a little so that walks sharing a corridor stay apart) and the
// letters it recorded at each junction (a dot on the junction; the exploration's letters above
// left, the driven route's below right) with where each search walk ended.
#pragma once

#include <string>
#include <vector>

#include "render/figure.h"
#include "sim/episode.h"

namespace plantsim::render {

/// The walks, dashed; false when there are none.
bool draw_tried_walks(GlCanvas& c, const std::vector<std::vector<Vec2>>& walks);
/// The labels as text over the panel of transform t; returns the legend entries of what it placed.
std::vector<LegendEntry> draw_plan_marks(Figure& fig, const PixelTransform& t, const std::vector<planner::PlanMark>& marks);

}  // namespace plantsim::render
