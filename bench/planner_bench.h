// `plantsim bench planner`: build and query times, vertices and edges of the fast visibility
// graph against the traditional one on worlds of 10 to 5000 rectangles, in one run (and the
// scaling chart of the three).
#pragma once

#include <string>

namespace plantsim::bench {

/// `shared_data` is the folder holding worlds/world_N*.json. With `chart_png`, also times the grid
/// planner and draws build-plus-first-query time against the obstacle count on log-log axes for
/// the visibility graph, the traditional one and the grid. Returns a process exit code.
int run_planner_bench(const std::string& shared_data, bool quick,
                      const std::string& chart_png = "");

}  // namespace plantsim::bench
