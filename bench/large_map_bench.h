// Cases of `plantsim bench planner` on large maps, the measurements the exact planner's speed
// work is judged by: the any-angle StarCraft maps ArcticStation and BigGameHunters (every query's
// length checked against the reference; preprocessing time and memory; per-query mean, median,
// p99 and max, cold and warm, beside Polyanya's figures recorded in ../shared/data/README.md),
// and random plants of 1,000 to 200,000 rectangles with the growth exponent of build plus first
// query fitted.
#pragma once

#include <string>
#include <vector>

#include "render/scaling_chart.h"

namespace plantsim::bench {

/// Returns a process exit code: 1 when a length differs from the reference or a query fails.
int run_anyangle_cases(const std::string& shared_data, bool quick);
/// Quick: 1,000 to 20,000 rectangles; otherwise up to 200,000. Returns a process exit code.
/// Each method's build plus first query against the size is appended to `curves`, if given.
int run_random_plant_scaling(bool quick, std::vector<render::ScalingSeries>* curves = nullptr);

}  // namespace plantsim::bench
