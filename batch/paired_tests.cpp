// McNemar's exact test and the paired t interval (see the header).
#include "batch/paired_tests.h"

#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>

namespace plantsim::batch {

double mcnemar_exact_p(std::int64_t lost, std::int64_t gained) {
  const std::int64_t n = lost + gained;
  if (n <= 0) return 1.0;
  const boost::math::binomial_distribution<double> split(static_cast<double>(n), 0.5);
  const double tail = boost::math::cdf(split, static_cast<double>(std::min(lost, gained)));
  return std::min(1.0, 2.0 * tail);
}

std::int64_t mcnemar_smallest_detectable(double level) {
  std::int64_t n = 1;
  while (n < 1000 && mcnemar_exact_p(n, 0) >= level) ++n;
  return n;
}

PairedDifference paired_difference(const std::vector<double>& differences, double level) {
  PairedDifference d;
  d.pairs = static_cast<std::int64_t>(differences.size());
  if (differences.empty()) return d;
  double sum = 0;
  for (double x : differences) sum += x;
  d.mean = sum / static_cast<double>(d.pairs);
  if (d.pairs < 2) return d;
  double squares = 0;
  for (double x : differences) squares += (x - d.mean) * (x - d.mean);
  d.sd = std::sqrt(squares / static_cast<double>(d.pairs - 1));
  const boost::math::students_t_distribution<double> t(static_cast<double>(d.pairs - 1));
  const double half =
      boost::math::quantile(t, 1 - level / 2) * d.sd / std::sqrt(static_cast<double>(d.pairs));
  d.interval = std::make_pair(d.mean - half, d.mean + half);
  return d;
}

}  // namespace plantsim::batch
