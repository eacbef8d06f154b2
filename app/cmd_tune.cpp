// `plantsim tune SCENARIO [--param KEY=LOW:HIGH ...] [--budget N] [--objective O] --out DIR`:
// episode parameters searched on the scenario's tuning episodes, proven on its validation ones.
#include <filesystem>
#include <iostream>
#include <tuple>
#include <vector>

#include "app/commands.h"
#include "tune/run_tune.h"
#include "util/fixed_text.h"

namespace plantsim::app {

namespace {

// What a tuning, a shard of one or a check did, in one or two lines.
void print_outcome(const std::string& scenario, const tune::TuneSpec& spec,
                   const tune::TuneOptions& o, const tune::TuneOutcome& out) {
  if (o.check_only) {
    std::cout << "tune: " << scenario << " is valid: " << spec.parameters.size() << " parameters, "
              << out.tuning_episodes << " tuning and " << out.validation_episodes
              << " validation episodes, up to " << 2 * spec.budget + 1 << " evaluations\n";
    return;
  }
  if (o.shard_count > 1) {
    std::cout << "tune: shard " << o.shard_index << "/" << o.shard_count << ": "
              << out.evaluations_run << " evaluations run, " << out.evaluations_reused
              << " read back -> " << o.out_dir
              << "/evaluations.jsonl (join the shards: plantsim tune SCENARIO --merge "
                 "FOLDER... --out DIR)\n";
    return;
  }
  if (out.evaluations_merged > 0)
    std::cout << "tune: " << out.evaluations_merged << " evaluations taken from "
              << o.merge_dirs.size() << " shard folder(s)\n";
  const tune::Proven& best = out.proven[out.best == "nlopt" ? 1 : 2];
  std::cout << "tune: " << out.evaluations_run << " evaluations run, " << out.evaluations_reused
            << " read back; validation: default " << out.proven[0].validation.stats.succeeded << "/"
            << out.validation_episodes << ", tuned (" << out.best << ") "
            << best.validation.stats.succeeded << "/" << out.validation_episodes
            << ", McNemar p = " << util::fixed(out.best_against_default.success_p, 4) << ", time "
            << util::fixed(100 * out.best_against_default.time_change, 1) << " % -> " << o.out_dir
            << "/best.json\n";
}

}  // namespace

std::function<int()> add_tune_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "tune",
      "Search episode parameters (NLopt, with random search beside it) on a scenario's tuning "
      "episodes; prove the best on its held-out validation episodes (docs/tune.md)");
  struct Options {
    tune::TuneRequest request;
    std::optional<int> budget;
    std::optional<double> min_wilson;
    std::string objective, method, out, shard = "0/1";
    std::vector<std::string> merge;
    bool quiet = false, no_figures = false, fresh = false, check = false;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("scenario", opt->request.scenario,
                  "Scenario YAML with a tune: section naming its validation worlds or seeds")
      ->required();
  cmd->add_option("--param", opt->request.parameters,
                  "KEY=LOW:HIGH, a number parameter of docs/config.md and its search bounds "
                  "(repeat; default: the scenario's tune.parameters, else pure pursuit's and the "
                  "docking approach's)");
  cmd->add_option("--budget", opt->budget,
                  "Evaluations for the optimiser, and as many for random search (default 60)")
      ->transform(decimal_whole_number());
  cmd->add_option("--objective", opt->objective,
                  "success_then_time (default), time, docking_error, contacts or success");
  cmd->add_option(
      "--method", opt->method,
      "NLopt's method: sbplx (default), sbplx-starts, bobyqa, neldermead, crs2 or isres");
  cmd->add_option("--min-wilson", opt->min_wilson,
                  "The constrained objectives' floor on the tuning episodes' Wilson low "
                  "(default: the default settings' own)");
  add_seed_option(cmd, opt->request.seed, "Seed of random search and NLopt's global methods");
  cmd->add_option("--threads", opt->request.threads, "Worker threads (default: one per core)")
      ->transform(decimal_whole_number())
      ->check(CLI::Range(0, 256));
  cmd->add_option("--out", opt->out, "Output folder (default results/tune_<scenario name>)");
  auto* shard = cmd->add_option(
      "--shard", opt->shard,
      "Run only shard i of n (i/n, from 0; n > 1): the default, then shard 0 NLopt's search and "
      "the others every (n-1)th of random search's points; no validation (join with --merge)");
  cmd->add_option("--merge", opt->merge,
                  "Shard folders of this tuning whose evaluations are taken in; what they lack "
                  "runs here, then the validation and the report")
      ->excludes(shard);
  cmd->add_flag("--quiet", opt->quiet, "No line per evaluation");
  cmd->add_flag("--no-figures", opt->no_figures, "Skip the report's charts");
  cmd->add_flag("--fresh", opt->fresh,
                "Discard the folder's earlier evaluations instead of resuming");
  cmd->add_flag("--check", opt->check, "Check the scenario, parameters and bounds; run nothing");
  auto plugin_files = std::make_shared<std::vector<std::string>>();
  add_plugin_option(cmd, *plugin_files);
  return [opt, cmd, plugin_files]() {
    load_plugins(*plugin_files);
    tune::TuneRequest r = opt->request;
    r.budget = opt->budget;
    r.min_wilson = opt->min_wilson;
    if (!opt->objective.empty()) r.objective = opt->objective;
    if (!opt->method.empty()) r.method = opt->method;
    const tune::TuneSpec spec = tune::load_tune_spec(r);
    tune::TuneOptions o;
    o.out_dir = opt->out.empty()
                    ? "results/tune_" + std::filesystem::path(r.scenario).stem().string()
                    : opt->out;
    o.fresh = opt->fresh;
    o.check_only = opt->check;
    o.progress = !opt->quiet;
    o.figures = !opt->no_figures;
    o.command = command_line(cmd);
    std::tie(o.shard_index, o.shard_count) = parse_shard(opt->shard);
    o.merge_dirs = opt->merge;
    print_outcome(r.scenario, spec, o, tune::run_tune(spec, o));
    return kExitOk;
  };
}

}  // namespace plantsim::app
