// The median of a bench's repeated timings (the upper of the middle two for an even count), the
// statistic every bench case reports: a run disturbed by the machine moves it least.
#pragma once

#include <algorithm>
#include <vector>

namespace plantsim::bench {

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace plantsim::bench
