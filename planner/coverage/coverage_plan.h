// Seed 004's full-coverage path by sub-regions: decompose the reachable cells into rectangles,
// order them (the document's CHNN, annealed Potts neurons, the proven optimum, or greedily),
// choose each region's sweep (start corner, lane direction) best for that order, and travel
// between them over the grid, from the start cell to the end cell. The document's metrics
// come with every plan.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "planner/coverage/coverage_grid.h"
#include "planner/coverage/coverage_params.h"

namespace plantsim::planner {

enum class RegionOrdering { kChnn, kPotts, kExact, kGreedy };

/// Above this many sub-regions the Hopfield network is not run (its n^3 work per step of the
/// state equation): the plan says so instead.
inline constexpr int kMaxNetworkRegions = 150;

struct CoverageMetrics {
  int reachable_cells = 0;
  int covered_cells = 0;
  double coverage = 0;      ///< covered / reachable
  int repeated_visits = 0;  ///< visits beyond the first, over all cells
  double repetition = 0;    ///< repeated visits / reachable cells (the document's rate)
  int turns = 0;            ///< changes of heading along the path (a U-turn counts two)
  int dead_ends = 0;  ///< stretches over covered cells that end on a new one (the robot had to go
                      ///< back over covered ground to go on covering; the way home not counted)
  double length_m = 0;
};

/// Visits, turns, dead ends and length of a cell path: one definition for every method.
CoverageMetrics measure_coverage(const CoverageGrid& grid, const std::vector<Cell>& path,
                                 Cell start);

struct CoveragePlan {
  bool ok = true;
  std::string failure;             ///< why there is no path (the network settled on no order)
  std::vector<Cell> cells;         ///< the path, cell by cell, start first (and the end last)
  std::vector<CellRect> regions;   ///< sub-regions (empty for the cell method)
  std::vector<int> order;          ///< regions in visiting order
  std::vector<int> sweeps;         ///< the sweep variant of each, per position
  std::vector<Cell> sweep_starts;  ///< the first cell of each sweep, per position
  double order_cost = 0;           ///< sum of D along the order, the way to the end included
  double greedy_cost = 0;
  std::optional<ExactOrder> exact;              ///< the search's account, for the exact method
  int network_valid = 0, network_restarts = 0;  ///< restarts that settled on a permutation
  CoverageMetrics metrics;
};

/// A plan that failed because `end` is given but off the grid or not in `reachable`; nullopt when
/// the end is fine (or there is none).
std::optional<CoveragePlan> unreachable_end(const CoverageGrid& grid,
                                            const std::vector<bool>& reachable,
                                            std::optional<Cell> end);

/// Appends `more` to `path`, skipping its first cell when it repeats the path's last.
void append_cells(std::vector<Cell>& path, const std::vector<Cell>& more);

CoveragePlan plan_region_coverage(const CoverageGrid& grid, Cell start, std::optional<Cell> end,
                                  RegionOrdering ordering, const CoverageParams& params = {});

}  // namespace plantsim::planner
