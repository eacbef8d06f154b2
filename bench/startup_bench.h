// `plantsim bench startup`: what a command that draws nothing costs to start (wall time and peak
// memory of whole processes), against the same command with OSMesa loaded at start as it was when
// the render library was linked to it (LD_PRELOAD of the library the canvas now opens on demand).
#pragma once

#include <string>

namespace plantsim::bench {

int run_startup_bench(const std::string& shared_data, bool quick);

}  // namespace plantsim::bench
