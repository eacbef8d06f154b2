// Seed 004's five methods planned on one world, as `plantsim coverage` and `plantsim
// coverage-study` both need them, and the document's own numbers to set beside the results.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planner/coverage/coverage_planner.h"
#include "worlds/world.h"

namespace plantsim::app {

/// The document's reported repetition rates (its own 40 x 20 m map, section 3).
inline constexpr double kDocumentRepetitionChnn = 0.0172;
inline constexpr double kDocumentRepetitionCells = 0.0287;

/// In the order figures show them.
inline const std::vector<std::string>& coverage_method_names() {
  static const std::vector<std::string> names{"coverage-chnn", "coverage-potts", "coverage-exact",
                                              "coverage-greedy", "coverage-cells"};
  return names;
}

struct CoverageRun {
  std::string method;
  std::unique_ptr<planner::CoveragePlanner> planner;
  planner::PlanResult result;
  bool planned() const { return result.status == planner::PlanStatus::kOk; }
};

/// Plans every method from the world's start to its charger's staging pose. A method that finds
/// no order (the network settling on none) is a run without a path; a goal that cannot be
/// reached throws std::invalid_argument naming the world.
std::vector<CoverageRun> plan_coverage_methods(const worlds::World& world,
                                               const planner::CoverageParams& params);

/// A method's plan in JSON: regions, order, costs, the network's share, the search's account,
/// the document's metrics.
nlohmann::ordered_json coverage_plan_json(const CoverageRun& run);

}  // namespace plantsim::app
