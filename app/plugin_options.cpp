// `--plugin FILE.so` of run, batch, tune and info: the plugins loaded before anything reads a
// configuration that may name their components.
#include "app/commands.h"
#include "plugins/plugin_loader.h"

namespace plantsim::app {

void add_plugin_option(CLI::App* cmd, std::vector<std::string>& files) {
  cmd->add_option("--plugin", files,
                  "A shared library of components (docs/plugins.md), loaded first; repeatable")
      ->take_all();
}

void load_plugins(const std::vector<std::string>& files) {
  for (const std::string& f : files) plugins::load_plugin(f, true);  // PluginError: exit 2
}

}  // namespace plantsim::app
