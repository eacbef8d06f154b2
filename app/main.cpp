// plantsim command line: parses arguments with CLI11 and dispatches to a subcommand.
// Bad input of any kind ends with a one-line message on stderr and exit code 2.
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "app/commands.h"
#include "worlds/world_error.h"

namespace plantsim::app {

std::string command_line(const CLI::App* sub) {
  std::string line = "plantsim " + sub->get_name();
  for (const CLI::Option* o : sub->get_options()) {
    if (o->count() == 0 || o->get_name() == "--help") continue;
    const bool positional = o->get_lnames().empty();
    for (const std::string& v : o->results()) line += positional ? " " + v : " --" + o->get_lnames().front() + " " + v;
    if (o->get_expected_max() == 0 && !positional) line += " --" + o->get_lnames().front();
  }
  return line;
}

std::string output_folder(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) throw std::invalid_argument("cannot create output folder '" + dir + "'");
  return dir;
}

}  // namespace plantsim::app

int main(int argc, char** argv) {
  CLI::App app{"plantsim: drive a wheeled robot through a plant to its charger, in Box2D"};
  app.require_subcommand(1);
  std::vector<std::pair<CLI::App*, std::function<int()>>> commands;
  auto remember = [&](std::function<int()> action) {
    commands.emplace_back(app.get_subcommands({}).back(), std::move(action));
  };
  remember(plantsim::app::add_plan_command(app));
  remember(plantsim::app::add_run_command(app));
  remember(plantsim::app::add_summarize_command(app));
  remember(plantsim::app::add_bench_command(app));
  remember(plantsim::app::add_config_command(app));
  remember(plantsim::app::add_compare_command(app));
  remember(plantsim::app::add_planners_command(app));
  remember(plantsim::app::add_batch_command(app));
  remember(plantsim::app::add_merge_command(app));
  remember(plantsim::app::add_generate_command(app));
  remember(plantsim::app::add_vary_command(app));
  remember(plantsim::app::add_coverage_command(app));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return plantsim::app::kExitBadInput;
  }
  try {
    for (auto& [sub, action] : commands)
      if (sub->parsed()) return action();
  } catch (const plantsim::worlds::WorldError& e) {
    std::cerr << "plantsim: " << e.what() << "\n";
    return plantsim::app::kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "plantsim: " << e.what() << "\n";
    return plantsim::app::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "plantsim: error: " << e.what() << "\n";
    return plantsim::app::kExitFailed;
  }
  return plantsim::app::kExitBadInput;
}
