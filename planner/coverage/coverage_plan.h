// Seed 004's full-coverage path: decompose the reachable cells into rectangles, order them
// (CHNN, exact or greedy), sweep each from its best corner, travel between them over the grid;
// and the document's comparison method, cell-by-cell coverage by confidence (uncovered first,
// straight on before turning) with a ring search for the nearest uncovered cell at dead ends.
// The document's metrics come with every plan.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "planner/coverage/coverage_grid.h"
#include "planner/coverage/region_order.h"

namespace plantsim::planner {

enum class RegionOrdering { kChnn, kExact, kGreedy };

struct CoverageMetrics {
  int reachable_cells = 0;
  int covered_cells = 0;
  double coverage = 0;        ///< covered / reachable
  int repeated_visits = 0;    ///< visits beyond the first, over all cells
  double repetition = 0;      ///< repeated visits / reachable cells (the document's rate)
  int turns = 0;              ///< changes of heading along the path (a U-turn counts two)
  int dead_ends = 0;          ///< times the robot had to cross covered cells to go on
  double length_m = 0;
};

/// Visits, turns and length of a cell path; dead ends are counted by the planners.
CoverageMetrics measure_coverage(const CoverageGrid& grid, const std::vector<Cell>& path, Cell start);

struct CoveragePlan {
  std::vector<Cell> cells;          ///< the path, cell by cell, start first
  std::vector<CellRect> regions;    ///< sub-regions (empty for the grid method)
  std::vector<int> order;           ///< regions in visiting order
  double order_cost = 0;            ///< sum of D_ij along the order
  std::optional<double> exact_cost; ///< the Held-Karp optimum, when the count allows
  double greedy_cost = 0;
  int chnn_settled = 0, chnn_restarts = 0;
  CoverageMetrics metrics;
};

CoveragePlan plan_region_coverage(const CoverageGrid& grid, Cell start, RegionOrdering ordering,
                                  const ChnnParams& chnn = {});
CoveragePlan plan_cell_coverage(const CoverageGrid& grid, Cell start);

}  // namespace plantsim::planner
