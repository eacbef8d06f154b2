// Planning the five coverage methods and describing their plans.
#include "app/coverage_runs.h"

#include <stdexcept>

#include "worlds/charger_placement.h"

namespace plantsim::app {

std::vector<CoverageRun> plan_coverage_methods(const worlds::World& world,
                                               const planner::CoverageParams& params) {
  planner::PlannerInput input = planner::planner_input(world, true);
  std::vector<CoverageRun> runs;
  for (const std::string& name : coverage_method_names()) {
    CoverageRun run{name, std::make_unique<planner::CoveragePlanner>(input, name, params), {}};
    run.result = run.planner->plan(world.start.position(), worlds::staging_pose(world).position());
    if (!run.planned() && run.planner->last_plan().ok)
      throw std::invalid_argument(world.source + ": " + run.result.note);
    runs.push_back(std::move(run));
  }
  return runs;
}

nlohmann::ordered_json coverage_plan_json(const CoverageRun& run) {
  const planner::CoveragePlan& p = run.planner->last_plan();
  nlohmann::ordered_json j;
  j["planned"] = run.planned();
  if (!run.planned()) {
    j["failure"] = run.result.note;
  }
  j["regions"] = p.regions.size();
  if (!p.regions.empty()) {
    j["order"] = p.order;
    j["sweeps"] = p.sweeps;
    j["order_cost"] = p.order_cost;
    j["greedy_cost"] = p.greedy_cost;
  }
  if (p.network_restarts > 0) {
    j["settled_on_a_permutation"] = p.network_valid;
    j["restarts"] = p.network_restarts;
  }
  if (p.exact) {
    j["searched"] = p.exact->searched;
    j["proven_optimal"] = p.exact->proven;
    j["lower_bound"] = p.exact->lower_bound;
    j["search_s"] = p.exact->seconds;
    j["prefixes"] = p.exact->prefixes;
  }
  const planner::CoverageMetrics& m = p.metrics;
  j["reachable_cells"] = m.reachable_cells;
  j["coverage"] = m.coverage;
  j["repetition"] = m.repetition;
  j["turns"] = m.turns;
  j["dead_ends"] = m.dead_ends;
  j["path_length_m"] = m.length_m;
  return j;
}

}  // namespace plantsim::app
