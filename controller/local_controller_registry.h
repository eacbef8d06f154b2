// The local controllers by name: the built-ins (pure pursuit, MPPI, DWB) and whatever plugins
// add (plugins/plugin_loader.h). A new built-in is its folder and one line in the .cpp.
#pragma once

#include <memory>

#include "controller/local_controller.h"
#include "util/component_registry.h"

namespace plantsim::controller {

using LocalControllerRegistry = util::ComponentRegistry<LocalControllerEntry>;

/// The registry, the built-ins added on first use.
LocalControllerRegistry& local_controllers();

/// The default: "pure-pursuit".
inline constexpr const char* kDefaultLocalController = "pure-pursuit";

}  // namespace plantsim::controller
