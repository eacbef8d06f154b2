// `plantsim bench sim`: simulation steps per second of whole docking episodes (controller,
// sensors and logging on) against bare Box2D stepping the same world, in one run.
#pragma once

#include <string>

namespace plantsim::bench {

int run_sim_bench(const std::string& shared_data, bool quick);

}  // namespace plantsim::bench
