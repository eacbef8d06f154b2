// What every registered component says about itself, whichever extension point it plugs into
// (an estimator, a local controller, ...): its name, one line of summary, its parameters (each
// with its section, bounds and default) and its capabilities, the facts render and the command
// line ask of it instead of comparing names. Header-only: installed for plugins.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "util/param_spec.h"

namespace plantsim::util {

struct ComponentInfo {
  std::string name;     ///< as configurations spell it: lower case, digits, '-' and '_'
  std::string summary;  ///< one line for `plantsim info`
  std::vector<ParamSpec> params;
  std::vector<std::string> capabilities;  ///< e.g. "samples-trajectories"
  std::string origin;  ///< "built-in", or the plugin file it came from (set by the registry)

  bool can(const std::string& capability) const {
    return std::find(capabilities.begin(), capabilities.end(), capability) != capabilities.end();
  }
};

}  // namespace plantsim::util
