// Assembling coverage paths from sub-region orders, and measuring them.
#include "planner/coverage/coverage_plan.h"

#include <algorithm>
#include <string>

namespace plantsim::planner {

void append_cells(std::vector<Cell>& path, const std::vector<Cell>& more) {
  for (std::size_t i = 0; i < more.size(); ++i)
    if (!(i == 0 && !path.empty() && path.back() == more[0])) path.push_back(more[i]);
}

CoverageMetrics measure_coverage(const CoverageGrid& grid, const std::vector<Cell>& path,
                                 Cell start) {
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
  m.repetition =
      m.reachable_cells ? static_cast<double>(m.repeated_visits) / m.reachable_cells : 0.0;
  m.turns = turns_along(path);
  m.length_m = path.empty() ? 0.0 : grid.cell_m() * (path.size() - 1.0);
  // A dead end: a stretch of the path over covered cells that ends on a new one (the robot had
  // to go back over covered ground to go on covering). The same count for every method; the way
  // home after the last new cell is not one.
  std::fill(visits.begin(), visits.end(), 0);
  bool over_covered = false;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const bool fresh = visits[grid.index(path[i])]++ == 0;
    if (fresh && over_covered) ++m.dead_ends;
    over_covered = !fresh && i > 0;
  }
  return m;
}

std::optional<CoveragePlan> unreachable_end(const CoverageGrid& grid,
                                            const std::vector<bool>& reachable,
                                            std::optional<Cell> end) {
  if (!end || (grid.inside(*end) && reachable[grid.index(*end)])) return std::nullopt;
  CoveragePlan plan;
  plan.ok = false;
  plan.failure = "the end cell cannot be reached from the start";
  return plan;
}

CoveragePlan plan_region_coverage(const CoverageGrid& grid, Cell start, std::optional<Cell> end,
                                  RegionOrdering ordering, const CoverageParams& params) {
  const std::vector<bool> reach = grid.reachable(start);
  if (auto failed = unreachable_end(grid, reach, end)) return *failed;
  CoveragePlan plan;
  plan.regions = grid.decompose(reach);
  if (plan.regions.empty()) return plan;
  const SweepModel model(grid, plan.regions, start, end, params.weights);
  const std::vector<int> greedy = greedy_order(model);
  plan.greedy_cost = model.best_sweeps(greedy).cost;
  switch (ordering) {
    case RegionOrdering::kChnn: {
      if (model.regions() > kMaxNetworkRegions) {
        plan.ok = false;
        plan.failure = std::to_string(model.regions()) +
                       " sub-regions: the Hopfield network is not run above " +
                       std::to_string(kMaxNetworkRegions) + " (its work per step grows as n^3)";
        return plan;
      }
      const HopfieldResult r = hopfield_order(model.region_distances(), params.chnn);
      plan.network_valid = r.valid;
      plan.network_restarts = r.restarts;
      if (!r.order) {
        plan.ok = false;
        plan.failure = "the Hopfield network settled on a valid order in 0 of " +
                       std::to_string(r.restarts) + " restarts";
        return plan;
      }
      plan.order = *r.order;
      break;
    }
    case RegionOrdering::kPotts: {
      const PottsResult r = potts_order(model.region_distances(), params.potts);
      plan.network_valid = r.settled_valid;
      plan.network_restarts = r.restarts;
      plan.order = r.order;
      break;
    }
    case RegionOrdering::kExact:
      plan.exact = exact_order(model, {greedy}, params.exact);
      plan.order = plan.exact->order;
      break;
    case RegionOrdering::kGreedy:
      plan.order = greedy;
      break;
  }
  const SweepModel::Sweeps sweeps = model.best_sweeps(plan.order);
  plan.sweeps = sweeps.variants;
  plan.order_cost = sweeps.cost;

  // The path: the way to each region's sweep, the sweep, and at last the way to the end.
  plan.cells.push_back(start);
  auto walk = [&](const std::vector<Cell>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (!(i == 0 && plan.cells.back() == cells[0])) plan.cells.push_back(cells[i]);
  };
  int last = SweepModel::kStart, last_variant = 0;
  for (std::size_t k = 0; k < plan.order.size(); ++k) {
    const int region = plan.order[k], variant = plan.sweeps[k];
    walk(model.travel(last, last_variant, region, variant));
    walk(model.variant(region, variant).cells);
    plan.sweep_starts.push_back(model.variant(region, variant).cells.front());
    last = region, last_variant = variant;
  }
  if (end) walk(model.travel_to_end(last, last_variant));
  plan.metrics = measure_coverage(grid, plan.cells, start);
  return plan;
}

}  // namespace plantsim::planner
