// Seed 004 behind the planner interface: "coverage" (sub-regions ordered by the CHNN, the
// document's method), "coverage-exact" (Held-Karp order), "coverage-greedy" (nearest region
// next) and "coverage-cells" (the document's cell-by-cell comparison method). The path covers
// every reachable cell from the start, then goes to the goal (the charger's staging pose), so
// that the robot sweeps the pit and docks. The last plan is kept for coverage figures.
#pragma once

#include "planner/coverage/coverage_plan.h"
#include "planner/planner.h"

namespace plantsim::planner {

enum class CoverageMethod { kChnn, kExact, kGreedy, kCells };

class CoveragePlanner : public Planner {
 public:
  CoveragePlanner(const PlannerInput& input, CoverageMethod method);
  std::string name() const override;
  PlanResult plan(Vec2 start, Vec2 goal) override;

  const CoverageGrid& grid() const { return grid_; }
  const CoveragePlan& last_plan() const { return last_; }

 private:
  CoverageGrid grid_;
  CoverageMethod method_;
  CoveragePlan last_;
  // The last query and its answer: an episode plans again what `plantsim coverage` has just
  // planned, and a coverage plan (CHNN restarts, the exact order for its gap) is not cheap.
  std::optional<std::pair<Vec2, Vec2>> last_query_;
  PlanResult last_result_;
};

/// The coverage planners' names, for the registry.
bool is_coverage_planner(std::string_view name);
CoverageMethod coverage_method(std::string_view name);

}  // namespace plantsim::planner
