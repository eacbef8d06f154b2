// Union of pseudo-angle intervals on the circle, split at the seam 0/4.
#include "planner/vg/angle_coverage.h"

#include <algorithm>

namespace plantsim::planner {

void AngleCoverage::add(double lo, double hi) {
  if (hi < lo) hi += kPseudoAnglePeriod;
  lo += kPseudoAngleSlack;
  hi -= kPseudoAngleSlack;
  if (!(lo < hi)) return;
  if (lo >= kPseudoAnglePeriod) {
    lo -= kPseudoAnglePeriod;
    hi -= kPseudoAnglePeriod;
  }
  if (hi <= kPseudoAnglePeriod) {
    insert(lo, hi);
  } else {  // the seam is not a real boundary: both pieces may touch it
    insert(lo, kPseudoAnglePeriod);
    insert(0.0, hi - kPseudoAnglePeriod);
  }
}

void AngleCoverage::insert(double lo, double hi) {
  auto it = intervals_.insert(
      std::lower_bound(intervals_.begin(), intervals_.end(), std::make_pair(lo, hi)), {lo, hi});
  // Merge only overlapping neighbours: open intervals that merely touch leave a gap.
  if (it != intervals_.begin() && it->first < std::prev(it)->second) {
    auto prev = std::prev(it);
    prev->second = std::max(prev->second, it->second);
    it = std::prev(intervals_.erase(it));
  }
  for (auto next = std::next(it); next != intervals_.end() && next->first < it->second;) {
    it->second = std::max(it->second, next->second);
    next = intervals_.erase(next);
  }
}

bool AngleCoverage::covers(double a) const {
  auto it =
      std::upper_bound(intervals_.begin(), intervals_.end(), a,
                       [](double x, const std::pair<double, double>& iv) { return x < iv.first; });
  return it != intervals_.begin() && a < std::prev(it)->second && a > std::prev(it)->first;
}

bool AngleCoverage::full() const {
  return intervals_.size() == 1 && intervals_[0].first <= 0.0 &&
         intervals_[0].second >= kPseudoAnglePeriod;
}

}  // namespace plantsim::planner
