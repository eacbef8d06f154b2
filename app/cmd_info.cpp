// `plantsim planners` and `plantsim config`: what the program offers, for scripts and users.
#include <iostream>

#include "app/commands.h"
#include "episode/episode_config_json.h"
#include "planner/planner.h"
#include "planner/registry.h"

namespace plantsim::app {

std::function<int()> add_planners_command(CLI::App& app) {
  app.add_subcommand("planners", "Print the planner names, comma separated");
  return []() {
    std::string line;
    for (const auto& n : planner::planner_names()) line += (line.empty() ? "" : ",") + n;
    std::cout << line << "\n";
    return kExitOk;
  };
}

std::function<int()> add_config_command(CLI::App& app) {
  app.add_subcommand("config",
                     "Print every episode parameter with its default, as a --config file");
  return []() {
    std::cout << episode::default_config_json();
    return kExitOk;
  };
}

}  // namespace plantsim::app
