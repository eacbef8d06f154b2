// The median of a scan's residuals and their median absolute deviation about it, exactly as two
// std::nth_element selections give them, in under half their time: up to 64 values are sorted
// by a bitonic network (compare-exchanges without branches, where nth_element's partitions
// mispredicted every other comparison on residuals) and the deviations then taken outward from
// the median, nearest first. More values go to nth_element.
#pragma once

#include <vector>

namespace plantsim::robot {

struct MedianSpread {
  double median;  ///< the (n/2)-th smallest value, 0-based (of two middle ones, the upper); of
                  ///< +0 and -0, either
  double mad;     ///< the (n/2)-th smallest |value - median|, bit for bit
};

/// Of `values` (reordered; at least one, none NaN).
MedianSpread median_spread(std::vector<double>& values);

}  // namespace plantsim::robot
