// The planners by name (see the header).
#include "planner/registry.h"

#include <algorithm>
#include <stdexcept>

#include "planner/coverage/coverage_planner.h"
#include "planner/gcr/gcr_planner.h"
#include "planner/grid/grid_astar.h"
#include "planner/maze/maze_planner.h"
#include "planner/mesh/interval_planner.h"
#include "planner/round/tangent_planner.h"
#include "planner/vg/vg_planner.h"

namespace plantsim::planner {

std::vector<std::string> planner_names() {
  return {"vg",
          "vg-traditional",
          "vg-round",
          "interval",
          "polyanya",
          "grid",
          "gcr",
          "gcr-shortcut",
          "maze-left",
          "maze-right",
          "maze-left-explore",
          "maze-right-explore",
          "maze-left-resimplified",
          "maze-right-resimplified",
          "coverage",
          "coverage-chnn",
          "coverage-potts",
          "coverage-exact",
          "coverage-greedy",
          "coverage-cells"};
}

std::vector<OptionSpec> planner_option_specs(std::string_view name) {
  if (name == "interval" || name == "polyanya") return mesh_planner_options();
  if (name == "grid") return grid_planner_options();
  if (name == "gcr" || name == "gcr-shortcut") return gcr_planner_options();
  const auto names = planner_names();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw std::invalid_argument("unknown planner '" + std::string(name) + "'");
  return {};
}

std::unique_ptr<Planner> make_planner(std::string_view name, const PlannerInput& input) {
  check_options(name, input.options, planner_option_specs(name));
  if (name == "vg") return std::make_unique<VisibilityGraphPlanner>(input);
  if (name == "vg-traditional") return std::make_unique<TraditionalVisibilityPlanner>(input);
  if (name == "vg-round") return std::make_unique<RoundTangentPlanner>(input);
  if (name == "interval") return std::make_unique<IntervalPlanner>(input);
  if (name == "polyanya")
    return std::make_unique<IntervalPlanner>(input, MeshKind::kConvexPolygons);
  if (name == "grid") return std::make_unique<GridPlanner>(input);
  if (name == "gcr") return std::make_unique<GcrPlanner>(input);
  if (name == "gcr-shortcut") return std::make_unique<GcrPlanner>(input, true);
  if (name == "maze-left") return std::make_unique<MazePlanner>(input, Hand::kLeft);
  if (name == "maze-right") return std::make_unique<MazePlanner>(input, Hand::kRight);
  if (name == "maze-left-explore") return std::make_unique<MazePlanner>(input, Hand::kLeft, true);
  if (name == "maze-right-explore") return std::make_unique<MazePlanner>(input, Hand::kRight, true);
  if (name == "maze-left-resimplified")
    return std::make_unique<MazePlanner>(input, Hand::kLeft, false, ThirdString::kResimplified);
  if (name == "maze-right-resimplified")
    return std::make_unique<MazePlanner>(input, Hand::kRight, false, ThirdString::kResimplified);
  if (is_coverage_planner(name)) return std::make_unique<CoveragePlanner>(input, name);
  throw std::invalid_argument("unknown planner '" + std::string(name) + "'");
}

}  // namespace plantsim::planner
