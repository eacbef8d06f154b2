// Distances between sub-regions and the three ways of ordering them.
#include "planner/coverage/region_order.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace plantsim::planner {

DistanceMatrix region_distances(const CoverageGrid& grid, const std::vector<CellRect>& regions, double w_cells,
                                double w_turns) {
  const std::size_t n = regions.size();
  DistanceMatrix d(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<Cell> cells;
    for (int r = regions[i].row; r < regions[i].row + regions[i].height; ++r)
      for (int c = regions[i].column; c < regions[i].column + regions[i].width; ++c) cells.push_back({c, r});
    const std::vector<int> dist = grid.distances_from(cells);
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      // The nearest cell of region j, and the turns on the way down to region i.
      Cell best{-1, -1};
      int best_d = std::numeric_limits<int>::max();
      for (int r = regions[j].row; r < regions[j].row + regions[j].height; ++r)
        for (int c = regions[j].column; c < regions[j].column + regions[j].width; ++c) {
          const int v = dist[grid.index({c, r})];
          if (v >= 0 && v < best_d) best_d = v, best = {c, r};
        }
      if (best.column < 0) {
        d[i][j] = 1e9;  // unreachable: never chosen while anything else is possible
        continue;
      }
      const int turns = turns_along(grid.descend(dist, best));
      d[i][j] = w_cells * best_d + w_turns * turns;
    }
  }
  return d;
}

double order_cost(const DistanceMatrix& d, const std::vector<int>& order) {
  double total = 0;
  for (std::size_t k = 1; k < order.size(); ++k) total += d[order[k - 1]][order[k]];
  return total;
}

std::optional<std::vector<int>> held_karp_order(const DistanceMatrix& d, int start, int max_regions) {
  const int n = static_cast<int>(d.size());
  if (n > max_regions) return std::nullopt;
  if (n == 1) return std::vector<int>{start};
  const std::size_t full = std::size_t{1} << n;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> cost(full * n, inf);
  std::vector<std::int8_t> parent(full * n, -1);  // n <= 20: 2^20 x 20 entries, about 190 MB
  cost[(std::size_t{1} << start) * n + start] = 0;
  for (std::size_t mask = 0; mask < full; ++mask) {
    if (!(mask >> start & 1)) continue;
    for (int last = 0; last < n; ++last) {
      const double c = cost[mask * n + last];
      if (c == inf) continue;
      for (int next = 0; next < n; ++next) {
        if (mask >> next & 1) continue;
        const std::size_t m2 = mask | (std::size_t{1} << next);
        const double c2 = c + d[last][next];
        if (c2 < cost[m2 * n + next]) cost[m2 * n + next] = c2, parent[m2 * n + next] = static_cast<std::int8_t>(last);
      }
    }
  }
  int last = 0;
  for (int k = 1; k < n; ++k)
    if (cost[(full - 1) * n + k] < cost[(full - 1) * n + last]) last = k;
  std::vector<int> order;
  std::size_t mask = full - 1;
  while (last >= 0) {
    order.push_back(last);
    const int p = parent[mask * n + last];
    mask &= ~(std::size_t{1} << last);
    last = p;
  }
  std::reverse(order.begin(), order.end());
  return order;
}

std::vector<int> greedy_order(const DistanceMatrix& d, int start) {
  const int n = static_cast<int>(d.size());
  std::vector<int> order{start};
  std::vector<bool> used(n, false);
  used[start] = true;
  for (int k = 1; k < n; ++k) {
    int best = -1;
    for (int j = 0; j < n; ++j)
      if (!used[j] && (best < 0 || d[order.back()][j] < d[order.back()][best])) best = j;
    used[best] = true;
    order.push_back(best);
  }
  return order;
}

ChnnResult chnn_order(const DistanceMatrix& dist, int start, const ChnnParams& p) {
  const int n = static_cast<int>(dist.size());
  ChnnResult result;
  if (n <= 2) {
    result.order = greedy_order(dist, start);
    return result;
  }
  // Distances scaled to at most 1, so that the weights below mean the same on every map.
  double dmax = 0;
  for (const auto& row : dist)
    for (double v : row)
      if (v < 1e8) dmax = std::max(dmax, v);
  std::vector<double> d(static_cast<std::size_t>(n) * n, 0.0);
  for (int x = 0; x < n; ++x)
    for (int y = 0; y < n; ++y) d[x * n + y] = dmax > 0 ? std::min(dist[x][y], 1e8) / dmax : 0.0;

  std::mt19937_64 rng(p.seed);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  double best_cost = std::numeric_limits<double>::infinity();
  // V[x][k]: how much region x is held at position k. Position 0 is the start's region.
  std::vector<double> v(static_cast<std::size_t>(n) * n), field(n);
  for (int restart = 0; restart < p.restarts; ++restart) {
    for (int x = 0; x < n; ++x)
      for (int k = 0; k < n; ++k)
        v[x * n + k] = k == 0 ? (x == start ? 1.0 : 0.0) : (x == start ? 0.0 : (1.0 + noise(rng)) / (n - 1));
    for (double t = p.t0; t > p.t_min; t *= p.cooling) {
      for (int sweep = 0; sweep < p.sweeps; ++sweep)
        for (int k = 1; k < n; ++k) {
          // Local field: distance to what is held just before and after, plus the penalty for
          // a region held at other positions too (each region once).
          double lowest = std::numeric_limits<double>::infinity();
          for (int x = 0; x < n; ++x) {
            if (x == start) continue;
            double near = 0, elsewhere = 0;
            for (int y = 0; y < n; ++y) {
              if (y == x) continue;
              near += d[x * n + y] * (v[y * n + k - 1] + (k + 1 < n ? v[y * n + k + 1] : 0.0));
            }
            for (int l = 1; l < n; ++l)
              if (l != k) elsewhere += v[x * n + l];
            field[x] = p.d * near + p.a * elsewhere;
            lowest = std::min(lowest, field[x]);
          }
          // Each position holds one region: a softmax over the regions (Potts neurons).
          double sum = 0;
          for (int x = 0; x < n; ++x)
            if (x != start) sum += v[x * n + k] = std::exp(-(field[x] - lowest) / t);
          for (int x = 0; x < n; ++x)
            if (x != start) v[x * n + k] /= sum;
        }
    }
    // Settled on a permutation matrix by itself?
    bool valid = true;
    for (int x = 0; x < n && valid; ++x) {
      int on_row = 0, on_col = 0;
      for (int k = 0; k < n; ++k) on_row += v[x * n + k] > 0.5, on_col += v[k * n + x] > 0.5;
      valid = on_row == 1 && on_col == 1;
    }
    result.settled_valid += valid;
    ++result.restarts;
    // Read out: at each position the most active region not yet placed.
    std::vector<int> order{start};
    std::vector<bool> used(n, false);
    used[start] = true;
    for (int k = 1; k < n; ++k) {
      int best = -1;
      for (int x = 0; x < n; ++x)
        if (!used[x] && (best < 0 || v[x * n + k] > v[best * n + k])) best = x;
      used[best] = true;
      order.push_back(best);
    }
    const double c = order_cost(dist, order);
    if (c < best_cost) best_cost = c, result.order = order;
  }
  return result;
}

}  // namespace plantsim::planner
