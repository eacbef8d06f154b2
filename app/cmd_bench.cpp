// `plantsim bench planner|sim|render|batch|startup|controllers`: one JSON line per case with its
// same-run baseline.
#include <filesystem>

#include "app/commands.h"
#include "bench/batch_bench.h"
#include "bench/controller_bench.h"
#include "bench/planner_bench.h"
#include "bench/plugin_bench.h"
#include "bench/render_bench.h"
#include "bench/sim_bench.h"
#include "bench/startup_bench.h"
#include "util/data_dir.h"

namespace plantsim::app {

std::function<int()> add_bench_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("bench", "Benchmarks, one JSON line per case with a same-run baseline");
  struct Options {
    std::string target;
    bool quick = false;
    std::string chart;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("target", opt->target, "What to measure")
      ->required()
      ->check(CLI::IsMember(
          {"planner", "sim", "render", "batch", "startup", "controllers", "plugins"}));
  cmd->add_flag("--quick", opt->quick, "Fewer repetitions and no slow baselines");
  cmd->add_option("--chart", opt->chart,
                  "planner: also time the grid and draw the log-log time chart into this PNG");
  auto plugin_files = std::make_shared<std::vector<std::string>>();
  add_plugin_option(cmd, *plugin_files);
  return [opt, plugin_files]() {
    load_plugins(*plugin_files);
    // The shared data from --data (given before or after the subcommand), or found beside the
    // checkout.
    const std::string data =
        std::filesystem::absolute(util::data_dir()).lexically_normal().string();
    if (!opt->chart.empty() && opt->target != "planner")
      throw std::invalid_argument("--chart is for `bench planner` only");
    if (opt->target == "sim") return bench::run_sim_bench(data, opt->quick);
    if (opt->target == "render") return bench::run_render_bench(data, opt->quick);
    if (opt->target == "batch") return bench::run_batch_bench(data, opt->quick);
    if (opt->target == "startup") return bench::run_startup_bench(data, opt->quick);
    if (opt->target == "controllers") return bench::run_controller_bench(data, opt->quick);
    if (opt->target == "plugins") return bench::run_plugin_bench(data, opt->quick);
    return bench::run_planner_bench(data, opt->quick, opt->chart);
  };
}

}  // namespace plantsim::app
