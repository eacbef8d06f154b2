// Cell-by-cell coverage by cell values and turn confidence, with ring search at dead zones.
#include "planner/coverage/cell_coverage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace plantsim::planner {
namespace {

// Angle in [0, pi] between two headings given as cell steps.
double angle_between(double ax, double ay, double bx, double by) {
  const double na = std::hypot(ax, ay), nb = std::hypot(bx, by);
  if (na == 0 || nb == 0) return 0;
  return std::acos(std::clamp((ax * bx + ay * by) / (na * nb), -1.0, 1.0));
}

}  // namespace

double turn_confidence(double angle, double k) { return k * (1.0 - angle / std::numbers::pi); }

std::optional<Cell> ring_search(const CoverageGrid& grid, Cell from, const std::vector<int>& visits,
                                const std::vector<bool>& reachable) {
  const int max_ring = std::max(grid.columns(), grid.rows());
  std::optional<Cell> best;
  long best_d2 = std::numeric_limits<long>::max();
  // Ring r holds the cells at Chebyshev distance r; a cell at Euclidean distance e lies in a
  // ring <= e, so once r * r passes the best squared distance nothing nearer is left.
  for (int r = 1; r <= max_ring && static_cast<long>(r) * r <= best_d2; ++r)
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        if (std::max(std::abs(dx), std::abs(dy)) != r) continue;
        const Cell c{from.column + dx, from.row + dy};
        if (!grid.inside(c) || !reachable[grid.index(c)] || visits[grid.index(c)] > 0) continue;
        const long d2 = static_cast<long>(dx) * dx + static_cast<long>(dy) * dy;
        if (d2 < best_d2 || (d2 == best_d2 && (c.row < best->row ||
                                               (c.row == best->row && c.column < best->column))))
          best_d2 = d2, best = c;
      }
  return best;
}

CoveragePlan plan_cell_coverage(const CoverageGrid& grid, Cell start, std::optional<Cell> end,
                                const CoverageParams& params) {
  const std::vector<bool> reach = grid.reachable(start);
  if (auto failed = unreachable_end(grid, reach, end)) return *failed;
  CoveragePlan plan;
  std::vector<int> visits(reach.size(), 0);
  int left = 0;
  for (std::size_t i = 0; i < reach.size(); ++i) left += reach[i];
  plan.cells.push_back(start);
  ++visits[grid.index(start)];
  --left;
  const double w_value = params.weights.cells, w_turn = params.weights.turns;
  int heading = 0;             // facing east at the start, as the document's figures do
  std::optional<Cell> target;  // the nearest uncovered cell while in a dead zone
  std::vector<int> target_dist;
  // Among equal scores: straight on, then left, right, back.
  static constexpr int turn_order[4] = {0, 1, 3, 2};
  while (left > 0) {
    const Cell at = plan.cells.back();
    bool uncovered_next = false;
    for (int h = 0; h < 4; ++h) {
      const Cell n = neighbour(at, h);
      uncovered_next = uncovered_next || (grid.free(n) && visits[grid.index(n)] == 0);
    }
    if (!uncovered_next && !target) {
      target = ring_search(grid, at, visits, reach);
      target_dist = grid.distances_from({*target});
    }
    if (uncovered_next) target.reset();
    int best = -1;
    double best_score = -std::numeric_limits<double>::infinity();
    for (int t : turn_order) {
      const int h = (heading + t) % 4;
      const Cell n = neighbour(at, h);
      if (!grid.free(n)) continue;  // value minus infinity
      double angle;
      if (target) {
        if (target_dist[grid.index(n)] >= target_dist[grid.index(at)])
          continue;  // keeps the escape short
        angle = angle_between(n.column - at.column, n.row - at.row, target->column - at.column,
                              target->row - at.row);
      } else {
        angle = t == 0 ? 0.0 : t == 2 ? std::numbers::pi : std::numbers::pi / 2;
      }
      const double score = w_value * cell_value(visits[grid.index(n)]) +
                           w_turn * turn_confidence(angle, params.turn_k);
      if (score > best_score) best_score = score, best = h;
    }
    const Cell n = neighbour(at, best);
    plan.cells.push_back(n);
    if (visits[grid.index(n)]++ == 0) --left;
    heading = best;
    if (target && n == *target) target.reset();
  }
  if (end)
    append_cells(plan.cells, grid.descend(grid.distances_from({*end}), plan.cells.back(), heading));
  plan.metrics = measure_coverage(grid, plan.cells, start);
  return plan;
}

}  // namespace plantsim::planner
