// What a method showed of its own working, drawn over a world panel: the walk it made before
// its answer (seed 003's exploration, seed 002's raw walk) as a pale band, seed 003's ring-search
// walks (dashed, each shifted a little so that walks sharing a corridor stay apart) and the
// letters it recorded at each junction (a dot on the junction; the exploration's letters above
// left, the driven route's below right) with where each search walk ended.
#pragma once

#include <string>
#include <vector>

#include "episode/episode_result.h"
#include "render/figure.h"

namespace plantsim::render {

/// The walks a method made before its answer: the exploration or raw walk as a pale band, the
/// search walks dashed; the legend entries of what it drew.
std::vector<LegendEntry> draw_walks_before_answer(GlCanvas& c, const episode::EpisodeLog& run);
/// The labels as text over the panel of transform t; returns the legend entries of what it placed.
std::vector<LegendEntry> draw_plan_marks(Figure& fig, const PixelTransform& t,
                                         const std::vector<planner::PlanMark>& marks);

}  // namespace plantsim::render
