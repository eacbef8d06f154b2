// Elapsed wall time in milliseconds, as planners report their build and query times.
#pragma once

#include <chrono>

namespace plantsim::util {

inline double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace plantsim::util
