// Loading plugins: a shared library opened (never closed: its components live in the
// registries), its ABI version checked, its registration function called with a registrar that
// checks every component before any is added, and each component tried once with its defaults.
// A bad plugin is refused whole with a message naming its file, before any episode.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace plantsim::plugins {

/// A plugin refused (the message names the file and what is wrong); the command line exits 2.
class PluginError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct LoadedPlugin {
  std::string path;                ///< as given
  bool from_command_line = false;  ///< given with --plugin (not named by a scenario)
  std::string canonical;
  /// The names it registered.
  std::vector<std::string> local_controllers, estimators, planners, dock_detectors;
};

/// Loads the plugin at `path` (once: a second load of the same file returns the first).
/// `from_command_line`: given with --plugin, so a printed re-run command must repeat it.
const LoadedPlugin& load_plugin(const std::string& path, bool from_command_line = false);

/// " --plugin FILE" for each plugin given on the command line, quoted for the shell: what a
/// printed re-run command adds so that it runs with the same components.
std::string command_line_plugin_arguments();

/// Every plugin loaded so far, in order.
std::vector<LoadedPlugin> loaded_plugins();

}  // namespace plantsim::plugins
