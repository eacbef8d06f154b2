// `plantsim run WORLD`: plan, drive and dock in the simulation; write results.
#include "app/commands.h"

namespace plantsim::app {

std::function<int()> add_run_command(CLI::App& app) {
  app.add_subcommand("run", "Simulate one docking episode");
  return []() { return kExitFailed; };
}

}  // namespace plantsim::app
