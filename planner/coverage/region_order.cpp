// The greedy order and the annealed Potts network.
#include "planner/coverage/region_order.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace plantsim::planner {
namespace {

constexpr double kUpdateBudget = 3e9;

}  // namespace

std::vector<int> greedy_order(const SweepModel& m) {
  const int n = m.regions();
  std::vector<int> order;
  std::vector<bool> used(n, false);
  int last = SweepModel::kStart, last_variant = 0;
  for (int k = 0; k < n; ++k) {
    int best = -1, best_variant = 0;
    double best_cost = std::numeric_limits<double>::infinity();
    for (int j = 0; j < n; ++j)
      for (int w = 0; !used[j] && w < m.variants(j); ++w)
        if (const double c = m.cost(last, last_variant, j, w); best < 0 || c < best_cost)
          best = j, best_variant = w, best_cost = c;
    used[best] = true;
    order.push_back(best);
    last = best, last_variant = best_variant;
  }
  return order;
}

PottsResult potts_order(const RegionDistances& dist, const PottsParams& p) {
  const int n = static_cast<int>(dist.between.size());
  PottsResult result;
  if (n == 0) return result;
  const double dmax = distance_scale(dist);
  std::vector<double> d(static_cast<std::size_t>(n) * n, 0.0), first(n), last(n);
  for (int x = 0; x < n; ++x) {
    first[x] = dist.from_start[x] / dmax;
    last[x] = dist.to_end[x] / dmax;
    for (int y = 0; y < n; ++y) d[x * n + y] = dist.between[x][y] / dmax;
  }
  std::mt19937_64 rng(p.seed);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  double best_cost = std::numeric_limits<double>::infinity();
  std::vector<double> v(static_cast<std::size_t>(n) * n), field(n);
  // Each restart costs n^3 updates per sweep and temperature: on large maps fewer restarts run,
  // so that the work stays near kUpdateBudget (the result says how many ran).
  int temperatures = 0;
  for (double t = p.t0; t > p.t_min; t *= p.cooling) ++temperatures;
  const double per_restart = static_cast<double>(n) * n * n * p.sweeps * temperatures;
  const int restarts =
      std::max(1, std::min(p.restarts, static_cast<int>(kUpdateBudget / per_restart)));
  for (int restart = 0; restart < restarts; ++restart) {
    for (double& x : v) x = (1.0 + noise(rng)) / n;
    for (double t = p.t0; t > p.t_min; t *= p.cooling) {
      for (int sweep = 0; sweep < p.sweeps; ++sweep)
        for (int k = 0; k < n; ++k) {
          // Local field: distance to what is held just before and after (the start before the
          // first position, the end after the last), plus the penalty for a region held at
          // other positions too.
          double lowest = std::numeric_limits<double>::infinity();
          for (int x = 0; x < n; ++x) {
            double near = (k == 0 ? first[x] : 0.0) + (k == n - 1 ? last[x] : 0.0), elsewhere = 0;
            for (int y = 0; y < n; ++y) {
              if (y == x) continue;
              near += (k > 0 ? d[y * n + x] * v[y * n + k - 1] : 0.0) +
                      (k + 1 < n ? d[x * n + y] * v[y * n + k + 1] : 0.0);
            }
            for (int l = 0; l < n; ++l)
              if (l != k) elsewhere += v[x * n + l];
            field[x] = p.d * near + p.a * elsewhere;
            lowest = std::min(lowest, field[x]);
          }
          double sum = 0;
          for (int x = 0; x < n; ++x) sum += v[x * n + k] = std::exp(-(field[x] - lowest) / t);
          for (int x = 0; x < n; ++x) v[x * n + k] /= sum;
        }
    }
    bool valid = true;
    for (int x = 0; x < n && valid; ++x) {
      int on_row = 0, on_col = 0;
      for (int k = 0; k < n; ++k) on_row += v[x * n + k] > 0.5, on_col += v[k * n + x] > 0.5;
      valid = on_row == 1 && on_col == 1;
    }
    result.settled_valid += valid;
    ++result.restarts;
    std::vector<int> order;
    std::vector<bool> used(n, false);
    for (int k = 0; k < n; ++k) {
      int best = -1;
      for (int x = 0; x < n; ++x)
        if (!used[x] && (best < 0 || v[x * n + k] > v[best * n + k])) best = x;
      used[best] = true;
      order.push_back(best);
    }
    double c = first[order.front()] + last[order.back()];
    for (int k = 1; k < n; ++k) c += d[order[k - 1] * n + order[k]];
    if (c < best_cost) best_cost = c, result.order = order;
  }
  return result;
}

}  // namespace plantsim::planner
