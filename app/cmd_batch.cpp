// `plantsim batch SCENARIO.yaml [--out DIR] [--shard i/n]` and `plantsim merge DIR... --out DIR`.
#include <filesystem>
#include <iostream>
#include <sstream>

#include "app/commands.h"
#include "batch/batch_runner.h"

namespace plantsim::app {
namespace {

std::pair<int, int> parse_shard(const std::string& text) {
  int i = 0, n = 0;
  char slash = 0;
  std::istringstream in(text);
  if (!(in >> i >> slash >> n) || slash != '/' || !in.eof() || n < 1 || i < 0 || i >= n)
    throw std::invalid_argument("--shard expects i/n with 0 <= i < n, got '" + text + "'");
  return {i, n};
}

}  // namespace

std::function<int()> add_batch_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("batch", "Run a scenario's episodes on all cores; resumable and splittable into shards");
  struct Options {
    std::string scenario, out, shard = "0/1";
    int threads = 0;
    bool quiet = false, no_figures = false;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("scenario", opt->scenario, "Scenario YAML (docs/batch.md)")->required();
  cmd->add_option("--out", opt->out, "Output folder (default results/batch_<scenario name>)");
  cmd->add_option("--shard", opt->shard, "Run only shard i of n (i/n, from 0)");
  cmd->add_option("--threads", opt->threads, "Worker threads (default: one per core)")->check(CLI::Range(0, 256));
  cmd->add_flag("--quiet", opt->quiet, "No progress bar");
  cmd->add_flag("--no-figures", opt->no_figures, "Skip the report's figures");
  return [opt]() {
    batch::RunOptions o;
    std::tie(o.shard_index, o.shard_count) = parse_shard(opt->shard);
    o.out_dir = opt->out.empty() ? "results/batch_" + std::filesystem::path(opt->scenario).stem().string() : opt->out;
    o.threads = opt->threads;
    o.progress = !opt->quiet;
    o.figures = !opt->no_figures;
    const batch::BatchOutcome r = batch::run_batch(opt->scenario, o);
    std::cout << "batch: " << r.episodes << " episodes in this shard, " << r.ran << " run now, " << r.skipped
              << " already done; " << r.docked << " of those run now docked, " << r.collisions << " collisions -> "
              << o.out_dir << "\n";
    return kExitOk;
  };
}

std::function<int()> add_merge_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("merge", "Join shard folders of one batch into one");
  struct Options {
    std::vector<std::string> dirs;
    std::string out;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("dirs", opt->dirs, "Shard output folders")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("--out", opt->out, "Merged output folder")->required();
  return [opt]() {
    const std::int64_t n = batch::merge_batches(opt->dirs, opt->out);
    std::cout << "merge: " << n << " episodes -> " << opt->out << "\n";
    return kExitOk;
  };
}

}  // namespace plantsim::app
