// Assembling coverage paths and measuring them.
#include "planner/coverage/coverage_plan.h"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace plantsim::planner {
namespace {

// Appends `more` to `path`, skipping its first cell when it repeats the path's last.
void append(std::vector<Cell>& path, const std::vector<Cell>& more) {
  for (std::size_t i = 0; i < more.size(); ++i)
    if (!(i == 0 && !path.empty() && path.back() == more[0])) path.push_back(more[i]);
}

}  // namespace

CoverageMetrics measure_coverage(const CoverageGrid& grid, const std::vector<Cell>& path, Cell start) {
  CoverageMetrics m;
  const std::vector<bool> reach = grid.reachable(start);
  std::vector<int> visits(reach.size(), 0);
  for (Cell c : path) ++visits[grid.index(c)];
  for (std::size_t i = 0; i < reach.size(); ++i) {
    if (!reach[i]) continue;
    ++m.reachable_cells;
    m.covered_cells += visits[i] > 0;
    m.repeated_visits += std::max(0, visits[i] - 1);
  }
  m.coverage = m.reachable_cells ? static_cast<double>(m.covered_cells) / m.reachable_cells : 0.0;
  m.repetition = m.reachable_cells ? static_cast<double>(m.repeated_visits) / m.reachable_cells : 0.0;
  m.turns = turns_along(path);
  m.length_m = path.empty() ? 0.0 : grid.cell_m() * (path.size() - 1.0);
  return m;
}

CoveragePlan plan_region_coverage(const CoverageGrid& grid, Cell start, RegionOrdering ordering, const ChnnParams& chnn) {
  CoveragePlan plan;
  plan.regions = grid.decompose(grid.reachable(start));
  if (plan.regions.empty()) return plan;
  int first = 0;
  for (std::size_t i = 0; i < plan.regions.size(); ++i)
    if (plan.regions[i].contains(start)) first = static_cast<int>(i);
  const DistanceMatrix d = region_distances(grid, plan.regions);
  const auto exact = held_karp_order(d, first);
  if (exact) plan.exact_cost = order_cost(d, *exact);
  const std::vector<int> greedy = greedy_order(d, first);
  plan.greedy_cost = order_cost(d, greedy);
  if (ordering == RegionOrdering::kChnn) {
    const ChnnResult r = chnn_order(d, first, chnn);
    plan.order = r.order;
    plan.chnn_settled = r.settled_valid;
    plan.chnn_restarts = r.restarts;
  } else if (ordering == RegionOrdering::kExact && exact) {
    plan.order = *exact;
  } else {
    plan.order = greedy;  // also when too many regions for the exact order (the note says so)
  }
  plan.order_cost = order_cost(d, plan.order);

  // Sweep each region from the corner nearest to where the robot is.
  plan.cells.push_back(start);
  int dead_ends = 0;
  for (int region : plan.order) {
    const CellRect& r = plan.regions[region];
    std::vector<Cell> best_travel, best_sweep;
    for (int corner = 0; corner < 4; ++corner) {
      const std::vector<Cell> s = sweep(r, corner);
      const std::vector<Cell> t = grid.travel(plan.cells.back(), s.front());
      if (!t.empty() && (best_travel.empty() || t.size() < best_travel.size())) best_travel = t, best_sweep = s;
    }
    // Crossing more than the step into the next region means passing covered ground.
    if (best_travel.size() > 2) ++dead_ends;
    append(plan.cells, best_travel);
    append(plan.cells, best_sweep);
  }
  plan.metrics = measure_coverage(grid, plan.cells, start);
  plan.metrics.dead_ends = dead_ends;
  return plan;
}

CoveragePlan plan_cell_coverage(const CoverageGrid& grid, Cell start) {
  // Attribute of a neighbour: 1 for uncovered, less 0.5 per visit; among equals the smallest
  // turn wins (straight, then left or right, then back). A robot with no uncovered neighbour
  // is at a dead point: it goes to the nearest uncovered cell (ring search = breadth first).
  CoveragePlan plan;
  const std::vector<bool> reach = grid.reachable(start);
  std::vector<int> visits(reach.size(), 0);
  int left = 0;
  for (std::size_t i = 0; i < reach.size(); ++i) left += reach[i];
  plan.cells.push_back(start);
  ++visits[grid.index(start)];
  --left;
  int heading = 0, dead_ends = 0;
  static constexpr int turn_order[4] = {0, 1, 3, 2};  // straight, left, right, back
  while (left > 0) {
    const Cell at = plan.cells.back();
    int best = -1;
    for (int t : turn_order) {
      const int h = (heading + t) % 4;
      const Cell n = neighbour(at, h);
      if (grid.free(n) && visits[grid.index(n)] == 0) {
        best = h;
        break;
      }
    }
    if (best >= 0) {
      const Cell n = neighbour(at, best);
      plan.cells.push_back(n);
      ++visits[grid.index(n)];
      --left;
      heading = best;
      continue;
    }
    ++dead_ends;
    const std::vector<int> dist = grid.distances_from({at});
    Cell target{-1, -1};
    int target_d = std::numeric_limits<int>::max();
    for (int r = 0; r < grid.rows(); ++r)
      for (int c = 0; c < grid.columns(); ++c) {
        const std::size_t i = grid.index({c, r});
        if (reach[i] && visits[i] == 0 && dist[i] >= 0 && dist[i] < target_d) target_d = dist[i], target = {c, r};
      }
    const std::vector<Cell> t = grid.travel(at, target);
    for (std::size_t i = 1; i < t.size(); ++i) {
      if (visits[grid.index(t[i])]++ == 0) --left;
      plan.cells.push_back(t[i]);
    }
    if (t.size() > 1) heading = heading_between(t[t.size() - 2], t.back());
  }
  plan.metrics = measure_coverage(grid, plan.cells, start);
  plan.metrics.dead_ends = dead_ends;
  return plan;
}

}  // namespace plantsim::planner
