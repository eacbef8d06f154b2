// The planners by name: every method family the command line, scenarios and Python can ask for.
// The registry sits above the families (each includes only planner/planner.h, the interface),
// so that no family depends on another through it.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "planner/planner.h"

namespace plantsim::planner {

/// Names accepted by make_planner, in the order reports list them.
std::vector<std::string> planner_names();

/// The options the named planner's family takes (empty for most); throws for an unknown name.
std::vector<OptionSpec> planner_option_specs(std::string_view name);

/// Builds the named planner; throws std::invalid_argument for an unknown name or an option its
/// family does not take. Coverage planners get seed 004's default parameters (CoveragePlanner
/// takes others).
std::unique_ptr<Planner> make_planner(std::string_view name, const PlannerInput& input);

}  // namespace plantsim::planner
