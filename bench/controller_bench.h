// `plantsim bench controllers`: the wall time of one control cycle of each local controller,
// median and 99th percentile, in one run on the same drive: Regulated Pure Pursuit (the
// baseline every ratio is against), MPPI at Nav2's default batch (2000 x 56) and DWB at
// nav2_bringup's 20 x 20 samples, following a plan through world_N200 with the clearance field
// of its boxes.
#pragma once

#include <string>

namespace plantsim::bench {

int run_controller_bench(const std::string& shared_data, bool quick);

}  // namespace plantsim::bench
