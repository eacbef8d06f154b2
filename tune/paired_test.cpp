// The paired statistics of a tuning's verdict.
#include "tune/paired_test.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plantsim::tune {

namespace {

/// Student's t 97.5 % quantile for `dof` degrees of freedom (exact table to 30, then the
/// Cornish-Fisher series, within 1e-3 of it).
double t_quantile_975(std::int64_t dof) {
  static const double table[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306,
                                 2.262,  2.228, 2.201, 2.179, 2.160, 2.145, 2.131, 2.120,
                                 2.110,  2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064,
                                 2.060,  2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof >= 1 && dof <= 30) return table[dof - 1];
  const double z = 1.959964, v = static_cast<double>(dof);
  return z + (z * z * z + z) / (4 * v) +
         (5 * std::pow(z, 5) + 16 * z * z * z + 3 * z) / (96 * v * v);
}

}  // namespace

double two_sided_binomial_p(std::int64_t k, std::int64_t n) {
  if (n <= 0) return 1.0;
  const std::int64_t low = std::min(k, n - k);
  // P(X <= low), summed in logs (n may be thousands).
  double tail = 0;
  for (std::int64_t i = 0; i <= low; ++i)
    tail += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) -
                     n * std::log(2.0));
  return std::min(1.0, 2.0 * tail);
}

PairedComparison compare_paired(const std::vector<EpisodeOutcome>& a,
                                const std::vector<EpisodeOutcome>& b) {
  if (a.size() != b.size()) throw std::invalid_argument("paired outcomes of different episodes");
  PairedComparison c;
  c.pairs = static_cast<std::int64_t>(a.size());
  std::vector<double> d;
  double a_time = 0;
  std::int64_t faster = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].id != b[i].id) throw std::invalid_argument("paired outcomes of different episodes");
    c.only_a += a[i].succeeded && !b[i].succeeded;
    c.only_b += b[i].succeeded && !a[i].succeeded;
    if (a[i].succeeded && b[i].succeeded) {
      d.push_back(b[i].time_s - a[i].time_s);
      a_time += a[i].time_s;
      faster += d.back() < 0;
    }
  }
  c.success_p = two_sided_binomial_p(c.only_b, c.only_a + c.only_b);
  c.both_docked = static_cast<std::int64_t>(d.size());
  if (d.empty()) return c;
  double mean = 0;
  for (double x : d) mean += x;
  mean /= d.size();
  double ss = 0;
  std::int64_t ties = 0;
  for (double x : d) ss += (x - mean) * (x - mean), ties += x == 0;
  c.time_difference_s = mean;
  c.time_change = a_time > 0 ? mean / (a_time / d.size()) : 0.0;
  if (d.size() > 1) {
    const double half = t_quantile_975(static_cast<std::int64_t>(d.size()) - 1) *
                        std::sqrt(ss / (d.size() - 1) / d.size());
    c.time_low_s = mean - half, c.time_high_s = mean + half;
  } else {
    c.time_low_s = c.time_high_s = mean;
  }
  c.time_p = two_sided_binomial_p(faster, c.both_docked - ties);
  return c;
}

}  // namespace plantsim::tune
