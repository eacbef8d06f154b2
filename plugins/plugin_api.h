// What a plugin is: a shared library that registers components by name with plantsim when it is
// loaded (`--plugin FILE.so` on run, batch and tune, `plugins:` in a scenario,
// plantsim.load_plugin() in Python). It exports two C symbols, which PLANTSIM_PLUGIN defines:
// the ABI version it was built against, and the function that hands its components to the
// registrar. Its components are then chosen, configured, swept, tuned and compared exactly as
// the built-ins are (docs/plugins.md). They see what the robot's side sees: readings, the map and
// the estimate, never the simulator (no sim/ header is installed). Installed for plugins.
#pragma once

#include "controller/local_controller.h"
#include "planner/registry.h"
#include "robot/dock_detector.h"
#include "robot/estimator_registry.h"

/// Raised whenever an installed header's types change layout: a plugin built against another
/// version is refused by name before any episode.
#define PLANTSIM_PLUGIN_ABI_VERSION 2

namespace plantsim::plugins {

/// Where a plugin's registration function puts its components. Each name must be new (a clash
/// with a built-in or another plugin's is refused, naming both files); each parameter's section
/// should be the component's name.
class Registrar {
 public:
  virtual ~Registrar() = default;
  virtual void add_local_controller(controller::LocalControllerEntry entry) = 0;
  virtual void add_estimator(robot::EstimatorEntry entry) = 0;
  /// A planner: it sees the robot's map (PlannerInput: the boxes, the floor, the margin).
  virtual void add_planner(planner::PlannerEntry entry) = 0;
  /// A dock detector: it sees the readings, the estimate and the map's charger.
  virtual void add_dock_detector(robot::DockDetectorEntry entry) = 0;
};

}  // namespace plantsim::plugins

/// The ABI version and registration function's names, as the loader looks them up.
#define PLANTSIM_PLUGIN_ABI_SYMBOL "plantsim_plugin_abi_version"
#define PLANTSIM_PLUGIN_REGISTER_SYMBOL "plantsim_plugin_register"

/// In one source file of the plugin: `PLANTSIM_PLUGIN(my_register)` where
/// `void my_register(plantsim::plugins::Registrar&)` adds the plugin's components.
#define PLANTSIM_PLUGIN(register_function)                                              \
  extern "C" __attribute__((visibility("default"))) int plantsim_plugin_abi_version() { \
    return PLANTSIM_PLUGIN_ABI_VERSION;                                                 \
  }                                                                                     \
  extern "C" __attribute__((visibility("default"))) void plantsim_plugin_register(      \
      plantsim::plugins::Registrar& registrar) {                                        \
    register_function(registrar);                                                       \
  }
