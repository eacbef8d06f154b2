// The paired tests of plantsim diff, a baseline against a candidate on the same episodes:
// McNemar's exact test of a success (a binomial on the discordant pairs) and the mean of paired
// differences with its Student t interval. The distributions are Boost.Math's (libboost-dev).
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace plantsim::batch {

/// McNemar's exact test, two-sided. `lost`: pairs that succeeded in the baseline only; `gained`:
/// in the candidate only. Under "no change" each discordant pair falls either way with
/// probability 1/2, so the p-value is min(1, 2 P(X <= min(lost, gained))), X ~ Binomial(lost +
/// gained, 1/2); 1 when no pair is discordant.
double mcnemar_exact_p(std::int64_t lost, std::int64_t gained);

/// The smallest number of discordant pairs, all one way, that McNemar's exact test finds at
/// `level` (6 at 0.05: 2 / 2^6 = 0.031): fewer episodes cannot show any change.
std::int64_t mcnemar_smallest_detectable(double level);

/// The mean of paired differences (candidate minus baseline) with its two-sided (1 - level)
/// Student t interval; no interval below two pairs.
struct PairedDifference {
  std::int64_t pairs = 0;
  double mean = 0, sd = 0;  ///< sd: the differences' sample standard deviation
  std::optional<std::pair<double, double>> interval;
};

PairedDifference paired_difference(const std::vector<double>& differences, double level);

}  // namespace plantsim::batch
