// The plantsim subcommands: each registers its options on the CLI11 app and runs when chosen.
// Exit codes are shared: 0 done, 1 the job ran but failed (no path, not docked), 2 bad input.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace plantsim::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;
inline constexpr int kExitBadInput = 2;

/// "plantsim SUB ARGS..." as typed (positional arguments and the options given), for reports.
std::string command_line(const CLI::App* sub);

/// The world argument of `run` and `compare` (any format the loaders read) with the MovingAI
/// query that gives a .map its start and charger.
void add_world_options(CLI::App* cmd, std::string& world, std::string& scen, int& query);

/// The transform every whole-number option takes: plain decimal digits (leading zeros dropped),
/// at most 2^64 - 1, before CLI11 converts them. CLI11 alone reads "010" as octal 8 and "0x10"
/// as 16, and an unsigned "-1" or any number past 2^64 - 1 as the largest value, so that three
/// different seeds ran one episode. The option's own range check follows it.
const CLI::Validator& decimal_whole_number();

/// Refuses nan and infinities for a number option (CLI11's ranges let NaN through: every
/// comparison with it is false). main() adds it to every floating-point option.
const CLI::Validator& finite_number();

/// `--seed`, from 0 to 2^64 - 1.
void add_seed_option(CLI::App* cmd, std::uint64_t& seed, const std::string& description);

/// Refuses (std::invalid_argument, before any work) an output file that is the input it is made
/// from (`vary W.json --out W.json` replaced the user's world with its variant).
void refuse_output_over_input(const std::string& out, const std::string& input);

/// `--shard i/n` of batch and tune: {i, n} with 0 <= i < n (std::invalid_argument otherwise).
std::pair<int, int> parse_shard(const std::string& text);

/// `--plugin FILE.so` (repeatable) on `cmd`, and the loading of what it names (before anything
/// reads a configuration; a bad plugin throws plugins::PluginError, an invalid_argument: exit 2).
void add_plugin_option(CLI::App* cmd, std::vector<std::string>& files);
void load_plugins(const std::vector<std::string>& files);

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
std::function<int()> add_tune_command(CLI::App& app);
std::function<int()> add_diff_command(CLI::App& app);
std::function<int()> add_info_command(CLI::App& app);

}  // namespace plantsim::app
