// `plantsim bench render`: frames per second at 1280 x 720 for world_N1000 with a 2000-point
// trajectory: render only, render + read back, render + PNG at the default and the fast
// setting, at 1x and 2x supersampling, in one run.
#pragma once

#include <string>

namespace plantsim::bench {

int run_render_bench(const std::string& shared_data, bool quick);

}  // namespace plantsim::bench
