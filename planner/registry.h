// The planners by name: every method family the command line, scenarios and Python can ask for,
// and whatever plugins add (plugins/plugin_api.h). Each entry says what render and the command
// line may ask of it (its capabilities) instead of their comparing names. The registry sits
// above the families (each includes only planner/planner.h, the interface), so that no family
// depends on another through it. A new built-in family is its folder and its lines in the .cpp.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "planner/planner.h"
#include "util/component_info.h"
#include "util/component_registry.h"

namespace plantsim::planner {

/// The capabilities a planner entry may list.
namespace capability {
/// Plans around obstacles grown by a disk (figures draw the margin rounded, not square).
inline constexpr const char* kRoundMargin = "round-margin";
/// Searches a navigation mesh: its graph is cells and portals, not vertices and edges.
inline constexpr const char* kSearchesAMesh = "searches-a-mesh";
/// Plans a full-coverage sweep of the floor (seed 004), not a way to one goal.
inline constexpr const char* kCoverage = "coverage";
}  // namespace capability

/// One planner: its name and capabilities, the options its family takes (planner_options.h: set
/// by name with `plantsim plan --option NAME=VALUE`, bounded), and its factory. `params` stays
/// empty: a planner's knobs are its options.
struct PlannerEntry : util::ComponentInfo {
  std::vector<OptionSpec> options;
  std::function<std::unique_ptr<Planner>(const PlannerInput&)> make;
};

using PlannerRegistry = util::ComponentRegistry<PlannerEntry>;

/// The registry, the built-ins added on first use, in the order reports list them.
PlannerRegistry& planners();

/// Names accepted by make_planner, in the order reports list them.
std::vector<std::string> planner_names();

/// The options the named planner's family takes (empty for most); throws for an unknown name.
std::vector<OptionSpec> planner_option_specs(std::string_view name);

/// True when the named planner lists `capability`; false for a name no planner has (a figure's
/// label that is not a planner's).
bool planner_can(std::string_view name, std::string_view capability);

/// Builds the named planner; throws std::invalid_argument for an unknown name or an option its
/// family does not take. Coverage planners get seed 004's default parameters (CoveragePlanner
/// takes others).
std::unique_ptr<Planner> make_planner(std::string_view name, const PlannerInput& input);

}  // namespace plantsim::planner
