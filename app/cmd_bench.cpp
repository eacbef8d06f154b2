// `plantsim bench planner|sim|render|batch`: one JSON line per case with its same-run baseline.
#include "app/commands.h"
#include "bench/batch_bench.h"
#include "bench/planner_bench.h"
#include "bench/render_bench.h"
#include "bench/sim_bench.h"

namespace plantsim::app {

std::function<int()> add_bench_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("bench", "Benchmarks, one JSON line per case with a same-run baseline");
  struct Options {
    std::string target;
    std::string shared_data = "../shared/data";
    bool quick = false;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("target", opt->target, "What to measure")->required()->check(CLI::IsMember({"planner", "sim", "render", "batch"}));
  cmd->add_option("--data", opt->shared_data, "Folder of the shared data")->check(CLI::ExistingDirectory);
  cmd->add_flag("--quick", opt->quick, "Fewer repetitions and no slow baselines");
  return [opt]() {
    if (opt->target == "sim") return bench::run_sim_bench(opt->shared_data, opt->quick);
    if (opt->target == "render") return bench::run_render_bench(opt->shared_data, opt->quick);
    if (opt->target == "batch") return bench::run_batch_bench(opt->shared_data, opt->quick);
    return bench::run_planner_bench(opt->shared_data, opt->quick);
  };
}

}  // namespace plantsim::app
