// `plantsim batch SCENARIO.yaml [--out DIR] [--shard i/n] [--min-success R] [--junit FILE]` and
// `plantsim merge DIR... --out DIR`. Both judge each configuration against the gate (the
// scenario's `gate:` and --min-success) and exit 1 when one is below its threshold.
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "app/commands.h"
#include "app/episode_outputs.h"
#include "app/output_kinds.h"
#include "batch/batch_gate.h"
#include "batch/batch_merge.h"
#include "batch/batch_runner.h"
#include "batch/episode_records.h"
#include "batch/episode_runner.h"
#include "util/atomic_file.h"
#include "util/input_file.h"
#include "worlds/json_input.h"
#include "worlds/known_keys.h"

namespace plantsim::app {
namespace {

/// The "made_by" stamp of a batch folder's summary.json as JUnit properties ("plantsim_" +
/// each key), none when it has none.
std::vector<std::pair<std::string, std::string>> stamp_of(const std::string& folder) {
  std::vector<std::pair<std::string, std::string>> out;
  try {
    const std::string path = folder + "/summary.json";
    const nlohmann::json j =
        worlds::parse_json_input(util::read_input_file(path, 64u << 20), path).at("made_by");
    for (const auto& [key, value] : j.items())
      out.emplace_back(key == "plantsim" ? "plantsim_version" : "plantsim_" + key,
                       value.is_string() ? value.get<std::string>() : value.dump());
  } catch (const std::exception&) {
  }
  return out;
}

// The gate options both commands take.
struct GateOptions {
  std::optional<double> min_success;
  std::string statistic;
  std::string junit;

  void add_to(CLI::App* cmd) {
    cmd->add_option("--min-success", min_success,
                    "Exit 1 when a configuration's success is below R (0..1); replaces the "
                    "scenario's gate.min_success")
        ->check(CLI::Range(0.0, 1.0));
    cmd->add_option("--gate-statistic", statistic,
                    "success_rate (default) or wilson_low (the 95 % Wilson lower bound)")
        ->check(CLI::IsMember({"success_rate", "wilson_low"}));
    cmd->add_option("--junit", junit,
                    "Also write a JUnit XML report, one test case per configuration");
  }

  // Before any episode runs: a report that could not be written would waste the batch. A
  // report inside the output folder (made by the batch) is one of the folder's own files; it may
  // not take the name of a file the batch writes there or a merge reads from its shards
  // (`--junit DIR/episodes.jsonl` once replaced the records with XML, and the next resume
  // reran every episode).
  std::vector<std::string> check_outputs(const std::string& out_dir,
                                         const std::vector<std::string>& shard_dirs = {}) const {
    if (junit.empty()) return {};
    namespace fs = std::filesystem;
    const fs::path report = fs::path(junit).lexically_normal();
    std::error_code ec;
    const fs::path report_dir = fs::weakly_canonical(fs::absolute(report, ec).parent_path(), ec);
    std::vector<std::string> batch_dirs = shard_dirs;
    batch_dirs.push_back(out_dir);
    for (const std::string& d : batch_dirs)
      if (report_dir == fs::weakly_canonical(fs::absolute(d, ec), ec) &&
          batch::is_batch_output_name(report.filename().string()))
        throw std::invalid_argument("--junit: '" + junit + "' is " + report.filename().string() +
                                    " of the batch folder '" + d + "'; name the report otherwise");
    if (fs::path(report).remove_filename().lexically_normal() ==
        (fs::path(out_dir) / "").lexically_normal()) {
      if (fs::exists(fs::symlink_status(junit)))
        util::check_output_file(junit, "--junit", junit_report_kind());
      return {report.filename().string()};
    }
    util::check_output_file(junit, "--junit", junit_report_kind());
    return {};
  }

  // Judges the records; prints failures; returns the exit code.
  batch::GateOverride as_override() const {
    batch::GateOverride o;
    o.min_success = min_success;
    if (!statistic.empty())
      o.statistic = batch::parse_gate_statistic(statistic, "--gate-statistic");
    return o;
  }

  /// `folder`'s records judged; junit.xml carries the stamp of its summary.json. `keep_junit`:
  /// the folder's outputs stand unchanged (a resume that ran nothing), so does a JUnit file there.
  int judge(const std::string& folder, const batch::Gate& scenario_gate, const std::string& suite,
            const char* who, const std::string& scenario_path = "", bool keep_junit = false) const {
    const std::vector<std::string> records = batch::read_episode_records(folder);
    const batch::Gate gate = as_override().applied_to(scenario_gate);
    const auto verdicts = batch::judge_configurations(records, gate);
    if (!junit.empty() && !(keep_junit && std::filesystem::is_regular_file(junit)))
      util::write_file_atomically(
          junit, batch::junit_xml(suite, verdicts, gate.statistic, stamp_of(folder),
                                  {scenario_path, folder}));
    int gated = 0, failed = 0;
    for (const auto& v : verdicts) gated += v.threshold.has_value(), failed += !v.passed;
    if (gated == 0) return kExitOk;
    std::cerr << batch::gate_failures_text(verdicts, gate.statistic);
    std::cout << who << ": gate " << (failed ? "FAILED" : "passed") << ": " << gated - failed
              << " of " << gated << " gated configurations at or above their threshold\n";
    return failed ? kExitFailed : kExitOk;
  }
};

/// What a batch did, on stdout.
void print_outcome(const batch::BatchOutcome& r, const std::string& out_dir) {
  std::cout << "batch: " << r.episodes << " episodes in this shard, " << r.ran << " run now, "
            << r.skipped << " already done; " << r.succeeded
            << " of those run now succeeded (docked, or caught in a pursuit), " << r.collisions
            << " collisions -> " << out_dir << "\n";
  if (r.outputs_kept)
    std::cout << "batch: nothing to run; the folder's report, summary and JUnit stand as the "
                 "run that made its records wrote them\n";
}

}  // namespace

std::function<int()> add_batch_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "batch",
      "Run a scenario's episodes on all cores; resumable, splittable into shards, a gate for CI");
  struct Options {
    std::string scenario, out, shard = "0/1", episode;
    int threads = 0;
    bool quiet = false, no_figures = false, fresh = false, check = false;
    bool accept_mixed_builds = false;
    GateOptions gate;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("scenario", opt->scenario, "Scenario YAML (docs/batch.md)")->required();
  cmd->add_option("--out", opt->out, "Output folder (default results/batch_<scenario name>)");
  cmd->add_option("--shard", opt->shard, "Run only shard i of n (i/n, from 0)");
  cmd->add_option("--threads", opt->threads, "Worker threads (default: one per core)")
      ->transform(decimal_whole_number())
      ->check(CLI::Range(0, 256));
  cmd->add_flag("--quiet", opt->quiet, "No progress bar");
  cmd->add_flag("--no-figures", opt->no_figures, "Skip the report's figures");
  cmd->add_flag("--fresh", opt->fresh, "Discard the folder's earlier episodes instead of resuming");
  cmd->add_flag("--check", opt->check,
                "Validate the scenario and count its episodes; run and write nothing");
  cmd->add_option("--episode", opt->episode,
                  "Run only this episode (its id in episodes.jsonl) and write its run folder "
                  "(figures, replay)");
  cmd->add_flag("--accept-mixed-builds", opt->accept_mixed_builds,
                "A resume whose records other builds ran: judge the mix (else its banner is not "
                "green)");
  opt->gate.add_to(cmd);
  auto plugin_files = std::make_shared<std::vector<std::string>>();
  add_plugin_option(cmd, *plugin_files);
  return [opt, cmd, plugin_files]() {
    load_plugins(*plugin_files);
    if (!opt->episode.empty()) {
      // One episode, exactly as the batch runs it, with the outputs of `plantsim run`.
      // Into a batch's own folder, it goes beside the records (episodes/<id>), never over them.
      const std::string id_folder = worlds::file_name_component(opt->episode);
      std::string destination = opt->out.empty() ? "results/episode_" + id_folder : opt->out;
      const bool into_batch =
          !opt->out.empty() && std::filesystem::is_regular_file(
                                   std::filesystem::symlink_status(opt->out + "/episodes.jsonl"));
      if (into_batch) {
        batch::check_batch_output_folder(opt->out, {});
        destination = opt->out + "/episodes/" + id_folder;
      }
      const batch::ReplayedEpisode e = batch::replay_batch_episode(opt->scenario, opt->episode);
      if (into_batch) std::filesystem::create_directories(opt->out + "/episodes");
      util::StagedFolder staged(destination, run_folder_names());
      write_run_folder(e.plant, e.result, e.config, staged.path(), command_line(cmd),
                       "episode " + e.id, false);
      staged.commit();
      std::cout << e.id << ": " << episode::status_name(e.result) << " -> " << staged.destination()
                << "\n";
      return e.result.succeeded() ? kExitOk : kExitFailed;
    }
    batch::RunOptions o;
    std::tie(o.shard_index, o.shard_count) = parse_shard(opt->shard);
    o.out_dir = opt->out.empty()
                    ? "results/batch_" + std::filesystem::path(opt->scenario).stem().string()
                    : opt->out;
    o.own_files = opt->gate.check_outputs(o.out_dir);
    o.threads = opt->threads;
    o.progress = !opt->quiet;
    o.figures = !opt->no_figures;
    o.fresh = opt->fresh;
    o.check_only = opt->check;
    o.gate = opt->gate.as_override();
    o.accept_mixed_builds = opt->accept_mixed_builds;
    const batch::BatchOutcome r = batch::run_batch(opt->scenario, o);
    if (opt->check) {
      std::cout << "batch: " << opt->scenario << " is valid: " << r.episodes
                << " episodes in this shard, scenario " << r.scenario_fingerprint << "\n";
      return kExitOk;
    }
    print_outcome(r, o.out_dir);
    return opt->gate.judge(o.out_dir, r.gate, std::filesystem::path(opt->scenario).stem().string(),
                           "batch", opt->scenario, r.outputs_kept);
  };
}

std::function<int()> add_merge_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "merge",
      "Join shard folders of one batch into one (refuses mixed scenarios and missing shards)");
  struct Options {
    std::vector<std::string> dirs;
    std::string out;
    bool allow_partial = false, accept_mixed_builds = false;
    std::string scenario;
    GateOptions gate;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("dirs", opt->dirs, "Shard output folders")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--out", opt->out, "Merged output folder")->required();
  cmd->add_option("--scenario", opt->scenario,
                  "The scenario file, when it no longer stands where the records say (it must be "
                  "their scenario by content)");
  cmd->add_flag("--allow-partial", opt->allow_partial,
                "Merge even when some of the scenario's episodes are missing");
  cmd->add_flag("--accept-mixed-builds", opt->accept_mixed_builds,
                "Shards that different builds ran: judge the mix (else its banner is not green)");
  opt->gate.add_to(cmd);
  return [opt]() {
    batch::MergeOptions m;
    m.own_files = opt->gate.check_outputs(opt->out, opt->dirs);
    m.allow_partial = opt->allow_partial;
    m.scenario = opt->scenario;
    m.gate = opt->gate.as_override();
    m.accept_mixed_builds = opt->accept_mixed_builds;
    const batch::MergeOutcome r = batch::merge_batches(opt->dirs, opt->out, m);
    std::cout << "merge: " << r.episodes << " of " << r.expected << " episodes -> " << opt->out
              << "\n";
    return opt->gate.judge(opt->out, r.gate, "merge", "merge", opt->scenario);
  };
}

}  // namespace plantsim::app
