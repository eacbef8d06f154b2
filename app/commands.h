// The plantsim subcommands: each registers its options on the CLI11 app and runs when chosen.
// Exit codes are shared: 0 done, 1 the job ran but failed (no path, not docked), 2 bad input.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace plantsim::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;
inline constexpr int kExitBadInput = 2;

/// "plantsim SUB ARGS..." as typed (positional arguments and the options given), for reports.
std::string command_line(const CLI::App* sub);

/// The world argument of `run` and `compare` (any format the loaders read) with the MovingAI
/// query that gives a .map its start and charger.
void add_world_options(CLI::App* cmd, std::string& world, std::string& scen, int& query);

/// Each returns the action to run when its subcommand was chosen.
std::function<int()> add_plan_command(CLI::App& app);
std::function<int()> add_run_command(CLI::App& app);
std::function<int()> add_summarize_command(CLI::App& app);
std::function<int()> add_bench_command(CLI::App& app);
std::function<int()> add_config_command(CLI::App& app);
std::function<int()> add_compare_command(CLI::App& app);
std::function<int()> add_planners_command(CLI::App& app);
std::function<int()> add_batch_command(CLI::App& app);
std::function<int()> add_merge_command(CLI::App& app);
std::function<int()> add_generate_command(CLI::App& app);
std::function<int()> add_coverage_command(CLI::App& app);
std::function<int()> add_coverage_study_command(CLI::App& app);
std::function<int()> add_vary_command(CLI::App& app);
std::function<int()> add_nav2_import_command(CLI::App& app);

}  // namespace plantsim::app
