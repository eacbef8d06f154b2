// A bitonic sorting network of 64 doubles, and the deviations walked outward from the median.
#include "robot/median_spread.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace plantsim::robot {
namespace {

constexpr int kNetwork = 64;

// One stage of the network: the pairs `half` apart within each block, ascending in blocks whose
// bit `size` is clear, descending in the others.
template <int size, int half>
void stage(double* a) {
  for (int base = 0; base < kNetwork; base += 2 * half) {
    const bool ascending = (base & size) == 0;
#pragma GCC unroll 32
    for (int i = base; i < base + half; ++i) {
      const double x = a[i], y = a[i + half];
      const double low = std::min(x, y), high = std::max(x, y);
      a[i] = ascending ? low : high;
      a[i + half] = ascending ? high : low;
    }
  }
}

template <int size, int half>
void merge(double* a) {
  stage<size, half>(a);
  if constexpr (half > 1) merge<size, half / 2>(a);
}

template <int size>
void sort_network(double* a) {
  merge<size, size / 2>(a);
  if constexpr (size < kNetwork) sort_network<2 * size>(a);
}

MedianSpread by_selection(std::vector<double>& r) {
  const auto mid = r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2);
  std::nth_element(r.begin(), mid, r.end());
  const double median = *mid;
  for (double& v : r) v = std::fabs(v - median);
  std::nth_element(r.begin(), mid, r.end());
  return {median, *mid};
}

}  // namespace

MedianSpread median_spread(std::vector<double>& values) {
  const long n = static_cast<long>(values.size());
  if (n > kNetwork) return by_selection(values);
  double a[kNetwork];
  std::copy(values.begin(), values.end(), a);
  std::fill(a + n, a + kNetwork, std::numeric_limits<double>::infinity());
  sort_network<2>(a);
  const long middle = n / 2;
  const double median = a[middle];
  // The median's own deviation (0) is the smallest; each further one is the nearer of the next
  // value below and the next above. |v - m| rounds as m - v below and v - m above.
  double deviation = 0;
  long below = middle - 1, above = middle + 1;
  for (long k = 0; k < middle; ++k) {
    const double down = below >= 0 ? median - a[below] : std::numeric_limits<double>::infinity();
    const double up = above < n ? a[above] - median : std::numeric_limits<double>::infinity();
    const bool take_down = down <= up;
    deviation = take_down ? down : up;
    below -= take_down;
    above += !take_down;
  }
  return {median, deviation};
}

}  // namespace plantsim::robot
