// Seed 004 behind the planner interface: "coverage-chnn" (sub-regions ordered by the document's
// Hopfield network; "coverage" is the same method), "coverage-potts" (plantsim's annealed Potts
// variant of the network), "coverage-exact" (the proven optimum order), "coverage-greedy"
// (nearest sweep next) and "coverage-cells" (the document's cell-by-cell comparison method).
// The path covers every reachable cell from the start and ends at the goal's cell (the
// charger's staging pose), so that the robot sweeps the pit and docks. The last plan is kept
// for coverage figures.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "planner/coverage/coverage_params.h"
#include "planner/coverage/coverage_plan.h"
#include "planner/planner.h"

namespace plantsim::planner {

enum class CoverageMethod { kChnn, kPotts, kExact, kGreedy, kCells };

class CoveragePlanner : public Planner {
 public:
  /// `name` is one the registry accepts (is_coverage_planner). The coverage parameters come
  /// apart from the point-to-point planners' input.
  CoveragePlanner(const PlannerInput& input, std::string_view name,
                  const CoverageParams& params = {});
  std::string name() const override { return name_; }
  PlanResult plan(Vec2 start, Vec2 goal) override;

  const CoverageGrid& grid() const { return grid_; }
  const CoveragePlan& last_plan() const { return last_; }
  CoverageMethod method() const { return method_; }

 private:
  std::optional<std::string> cover(const Cell& first, const Cell& last);
  CoverageGrid grid_;
  std::string name_;
  CoverageMethod method_;
  CoverageParams params_;
  CoveragePlan last_;
  // The last query and its answer: an episode plans again what `plantsim coverage` has just
  // planned, and a coverage plan (network restarts, the exact search) is not cheap.
  std::optional<std::pair<Vec2, Vec2>> last_query_;
  PlanResult last_result_;
};

/// The coverage planners' names, for the registry.
bool is_coverage_planner(std::string_view name);
CoverageMethod coverage_method(std::string_view name);

}  // namespace plantsim::planner
