// `plantsim bench planner`: build and query times, vertices and edges of the fast visibility
// graph against the traditional one on worlds of 10 to 5000 rectangles, in one run.
#pragma once

#include <string>

namespace plantsim::bench {

/// `shared_data` is the folder holding worlds/world_N*.json. Returns a process exit code.
int run_planner_bench(const std::string& shared_data, bool quick);

}  // namespace plantsim::bench
