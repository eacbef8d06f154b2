// `plantsim bench plugins --plugin FILE.so`: what a component costs when it comes from a plugin
// rather than built in, on the same code: the example plugin's Stanley follower
// (examples/plugin), compiled into plantsim for this bench and loaded from the plugin built out of
// the tree, each stepped through the same recorded drive. The ratio is the plugin's per-call time
// over the built-in's, in the same run (issue 86's target: within 3 %).
#pragma once

#include <string>

namespace plantsim::bench {

/// Exit 2 when no loaded plugin registered "stanley".
int run_plugin_bench(const std::string& shared_data, bool quick);

}  // namespace plantsim::bench
