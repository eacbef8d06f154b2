// Seed 004's comparison method, coverage cell by cell (its section 1): every cell carries a
// value (1 uncovered, 0.5 less per visit, minus infinity for obstacles) and each step goes to
// the neighbour with the best w1 * value + w2 * turn confidence. The document's turn-confidence
// formula (1) is missing from its text; what it says of it is kept: confidence falls as the
// turn grows, beta = K (1 - dtheta / pi) with dtheta the turn to the neighbour, and once the
// robot is in a dead zone (no uncovered neighbour) beta = K (1 - dphi / pi) with dphi the angle
// between the neighbour and the nearest uncovered cell, found by the document's ring search
// (rings of growing Euclidean radius around the dead point). Departure: a dead zone's steps are
// chosen among those that shorten the way to that cell on the grid, so the escape cannot walk
// into a wall between them; the document's dwell cells are not modelled (plantsim's worlds
// name no key components).
#pragma once

#include <optional>

#include "planner/coverage/coverage_plan.h"

namespace plantsim::planner {

/// The cell value the document gives a free cell after `visits` visits.
inline double cell_value(int visits) { return 1.0 - 0.5 * visits; }
/// The turn confidence for a turn (or, in a dead zone, a deviation) of `angle` in [0, pi].
double turn_confidence(double angle, double k);

/// The nearest uncovered reachable cell to `from` by Euclidean distance, rings outward
/// (ties: lowest row, then lowest column).
std::optional<Cell> ring_search(const CoverageGrid& grid, Cell from, const std::vector<int>& visits,
                                const std::vector<bool>& reachable);

CoveragePlan plan_cell_coverage(const CoverageGrid& grid, Cell start, std::optional<Cell> end,
                                const CoverageParams& params = {});

}  // namespace plantsim::planner
