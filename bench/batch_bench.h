// `plantsim bench batch`: docking episodes per second on all cores, for world_N200 and each
// plant scenario, and the time of 1000 episodes on world_N200, against one core in the same run.
#pragma once

#include <string>

namespace plantsim::bench {

int run_batch_bench(const std::string& shared_data, bool quick);

}  // namespace plantsim::bench
