// `plantsim info`: every registered component (the built-ins and those of the plugins given with
// --plugin) with its origin, summary, capabilities and parameters (default and bounds), as the
// configuration spells them: what a user needs to choose, configure, sweep and tune it.
#include <iostream>

#include "app/commands.h"
#include "controller/local_controller_registry.h"
#include "planner/registry.h"
#include "robot/dock_detector.h"
#include "robot/estimator_registry.h"
#include "robot/travel_registry.h"
#include "sim/sensor_model.h"
#include "util/c_number.h"

namespace plantsim::app {

namespace {

void print_component(const util::ComponentInfo& c) {
  std::cout << "  " << c.name << "  (" << c.origin << ")\n    " << c.summary << "\n";
  if (!c.capabilities.empty()) {
    std::cout << "    capabilities:";
    for (const std::string& k : c.capabilities) std::cout << " " << k;
    std::cout << "\n";
  }
  for (const util::ParamSpec& p : c.params) {
    const char* kind = p.kind == util::ParamKind::kFlag    ? "flag"
                       : p.kind == util::ParamKind::kWhole ? "whole"
                                                           : "real";
    std::cout << "    " << p.path() << " = " << util::c_general(p.default_value) << "  " << kind
              << " in " << (p.above ? "(" : "[") << util::c_general(p.lo) << ", "
              << util::c_general(p.hi) << "]" << (p.doc.empty() ? "" : "  " + p.doc) << "\n";
  }
}

/// A planner's options, set by name with `plantsim plan --option NAME=VALUE`.
void print_options(const std::vector<planner::OptionSpec>& options) {
  for (const planner::OptionSpec& o : options)
    std::cout << "    option " << o.name << " = " << util::c_general(o.default_value) << "  "
              << (o.integer ? "whole" : "real") << " in [" << util::c_general(o.min) << ", "
              << util::c_general(o.max) << "]" << (o.meaning.empty() ? "" : "  " + o.meaning)
              << "\n";
}

template <typename Registry>
void print_registry(const std::string& title, const std::string& key, const Registry& r) {
  std::cout << title << " (" << key << "):\n";
  for (const auto* e : r.entries()) print_component(*e);
}

}  // namespace

std::function<int()> add_info_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "info", "List the components (built-in and the plugins') with their parameters and bounds");
  auto plugin_files = std::make_shared<std::vector<std::string>>();
  add_plugin_option(cmd, *plugin_files);
  return [plugin_files]() {
    load_plugins(*plugin_files);
    print_registry("travel modes", "travel", robot::travel_modes());
    print_registry("local controllers", "local_controller", controller::local_controllers());
    print_registry("estimators", "localization.estimator", robot::estimators());
    print_registry("dock detectors", "docking.detector", robot::dock_detectors());
    std::cout << "sensor models (the simulator's, read in this order; not a plugin's):\n";
    for (const auto* e : sim::sensor_models().entries()) print_component(*e);
    std::cout << "planners (planner):\n";
    for (const auto* e : planner::planners().entries()) {
      print_component(*e);
      print_options(e->options);
    }
    return kExitOk;
  };
}

}  // namespace plantsim::app
