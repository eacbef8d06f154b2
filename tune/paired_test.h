// Two settings compared on the same episodes (paired): McNemar's exact test on the episodes only
// one of them docked, and the time to dock on the episodes both docked (mean difference with its
// 95 % interval, and the exact sign test).
#pragma once

#include <cstdint>
#include <vector>

#include "tune/objective.h"

namespace plantsim::tune {

struct PairedComparison {
  std::int64_t pairs = 0;
  std::int64_t only_b = 0, only_a = 0;  ///< episodes only the second (b) or only the first docked
  double success_p = 1;                 ///< McNemar's exact two-sided p-value
  std::int64_t both_docked = 0;
  double time_difference_s = 0;            ///< mean of b - a over the episodes both docked
  double time_low_s = 0, time_high_s = 0;  ///< its 95 % interval (Student's t)
  double time_p = 1;                       ///< the sign test's exact two-sided p-value
  double time_change = 0;  ///< the mean difference over a's mean time on those episodes
};

/// `a` and `b` are the same episodes in the same order (throws std::invalid_argument otherwise).
PairedComparison compare_paired(const std::vector<EpisodeOutcome>& a,
                                const std::vector<EpisodeOutcome>& b);

/// P(|X - n/2| >= |k - n/2|) for X ~ Binomial(n, 1/2): the exact two-sided p-value.
double two_sided_binomial_p(std::int64_t k, std::int64_t n);

}  // namespace plantsim::tune
