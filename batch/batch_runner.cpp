// The batch engine: a scenario checked whole before its first episode, the output folder
// locked, earlier records resumed, the episodes spread over threads with each record appended
// and flushed as it finishes, then the report.
#include "batch/batch_runner.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "batch/batch_report.h"
#include "batch/episode_record.h"
#include "batch/episode_records.h"
#include "batch/episode_runner.h"
#include "batch/episode_space.h"
#include "batch/progress.h"
#include "batch/record_paths.h"
#include "batch/scenario_setup.h"
#include "episode/episode_work.h"
#include "plugins/plugin_loader.h"
#include "util/atomic_file.h"
#include "util/folder_lock.h"
#include "util/input_file.h"
#include "util/thread_team.h"
#include "worlds/world_error.h"
#include "worlds/world_loader.h"

namespace plantsim::batch {
namespace {

using nlohmann::json;

/// The work is bounded before it starts: the physics steps these episodes may ask for.
void check_step_bound(const std::string& scenario_path, const BatchSpec& spec,
                      const std::vector<episode::EpisodeConfig>& configs,
                      const std::vector<Episode>& mine) {
  double steps = 0;
  for (const Episode& e : mine) {
    const episode::EpisodeConfig& c = configs[e.controller * spec.faults.size() + e.fault];
    steps += std::ceil(c.timeout_s / c.step.dt_s);
  }
  if (steps > kMaxBatchSteps)
    throw std::invalid_argument(
        scenario_path + ": this run asks for " + std::to_string(static_cast<long long>(steps)) +
        " physics steps (timeout_s / step.dt_s summed over its episodes), more than the limit of "
        "1e10 (docs/batch.md): fewer episodes, shorter timeouts, or shards (--shard i/n)");
}

void make_output_folder(const RunOptions& o) {
  check_batch_output_folder(o.out_dir, o.own_files);
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (ec || !std::filesystem::is_directory(o.out_dir))
    throw std::invalid_argument("output folder '" + o.out_dir + "' cannot be created" +
                                (ec ? ": " + ec.message() : ""));
}

/// Resume keeps the records of this scenario's episodes, once each (by id: an episode's index
/// depends on the order of the scenario's lists, its id does not); the rest run again. Read as
/// a stream: memory grows with the records kept, not with the file. Returns the ids done; the
/// lines it could not use are cut from the file and counted in `cut`.
std::set<std::string> resume(const std::string& jsonl, const RunOptions& o,
                             const EpisodeSpace& episodes, const std::string& fingerprint,
                             std::int64_t& cut) {
  std::vector<std::string> existing;
  std::set<std::string> done;
  std::int64_t foreign = 0;
  const JsonlScan scan = scan_jsonl(jsonl, [&](std::string&& line) {
    const json j = json::parse(line);
    const std::string theirs = j["scenario"].get<std::string>();
    if (theirs != fingerprint)
      throw std::invalid_argument("output folder '" + o.out_dir +
                                  "' holds episodes of another scenario (fingerprint " + theirs +
                                  ", this one " + fingerprint +
                                  "): choose another --out, or --fresh to discard them");
    const std::string id = j["id"].get<std::string>();
    if (!episodes.find(id) || !done.insert(id).second) {
      ++foreign;  // not one of this scenario's episodes, or a second copy
      return;
    }
    existing.push_back(std::move(line));
  });
  cut = scan.bad_lines + scan.torn_tail + foreign;
  if (cut > 0) {
    // Resume keeps what it can use and reruns the rest; the file is rewritten without them.
    std::string kept;
    for (const std::string& line : existing) kept += line + "\n";
    util::write_file_atomically(jsonl, kept);
    std::fprintf(stderr,
                 "batch: warning: cut %lld malformed, unfinished, repeated or foreign line(s) from "
                 "%s; their episodes run again%s\n",
                 static_cast<long long>(cut), jsonl.c_str(),
                 scan.first_problem.empty() ? "" : (" (" + scan.first_problem + ")").c_str());
  }
  return done;
}

/// episodes.jsonl opened for appending, never through a link (the folder was checked;
/// O_NOFOLLOW closes the race).
std::FILE* open_for_append(const std::string& jsonl) {
  const int fd =
      ::open(jsonl.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  std::FILE* out = fd >= 0 ? ::fdopen(fd, "ab") : nullptr;
  if (!out) {
    if (fd >= 0) ::close(fd);
    throw std::invalid_argument(util::system_error_text("cannot append to " + jsonl));
  }
  return out;
}

/// Everything the episodes of a run share.
struct RunContext {
  const BatchSpec& spec;
  const ScenarioWorlds& loaded;
  const std::vector<episode::EpisodeConfig>& configs;
  const ScenarioIdentity& scenario;
  const RunOptions& options;
};

/// Runs `todo` on the options' threads, each record appended to `out` and flushed as its episode
/// finishes (a killed batch loses at most the episode being written; a full disk stops the batch
/// at once instead of simulating episodes whose lines are lost). The first error stops all.
void run_episodes(const RunContext& run, const std::vector<Episode>& todo, std::FILE* out,
                  const std::string& jsonl, BatchOutcome& outcome) {
  std::mutex write_mutex;
  std::atomic<std::size_t> next{0};
  Progress progress(static_cast<std::int64_t>(todo.size()), run.options.progress);
  std::exception_ptr failure;
  auto worker = [&]() {
    try {
      // Inside the try: a thread short of memory for its runner ends the batch with a message.
      EpisodeRunner runner(run.spec, run.loaded.worlds, run.loaded.contents, run.configs,
                           run.options.steering);
      for (std::size_t k = next++; k < todo.size(); k = next++) {
        const Episode& e = todo[k];
        if (run.options.steering.interrupted && run.options.steering.interrupted())
          throw BatchInterrupted("the batch was interrupted; its finished episodes are in " +
                                 jsonl);
        const EpisodeRunner::Run r = runner.run(e);
        const std::string line = record_line(e, run.spec, run.scenario, r.plant, r.result,
                                             r.optimal_m, r.shortest_possible_m) +
                                 "\n";
        {
          std::lock_guard lock(write_mutex);
          if (std::fwrite(line.data(), 1, line.size(), out) != line.size() || std::fflush(out) != 0)
            throw std::runtime_error(util::system_error_text("cannot append to " + jsonl));
          ++outcome.ran;
          outcome.succeeded += r.result.succeeded();
          outcome.collisions += r.result.collisions;
        }
        progress.tick();
      }
    } catch (...) {
      std::lock_guard lock(write_mutex);
      if (!failure) failure = std::current_exception();
      next = todo.size();
    }
  };
  const int threads = run.options.threads > 0 ? run.options.threads
                                              : std::max(1u, std::thread::hardware_concurrency());
  util::run_on_threads(threads, worker);
  const bool synced = ::fsync(::fileno(out)) == 0 || errno == EINVAL;
  const std::string sync_error = synced ? "" : util::system_error_text("cannot sync " + jsonl);
  if (std::fclose(out) != 0 && !failure)
    throw std::runtime_error(util::system_error_text("cannot close " + jsonl));
  if (failure) std::rethrow_exception(failure);
  if (!synced) throw std::runtime_error(sync_error);
}

void write_report(const RunContext& run, const std::string& scenario_path,
                  const util::MadeBy& made_by) {
  const RunOptions& o = run.options;
  const std::vector<std::string> records = read_records(o.out_dir + "/episodes.jsonl");
  const std::vector<FailedEpisode> failures =
      o.figures ? failure_gallery(records, run.spec, run.loaded, run.configs, kGalleryEpisodes)
                : std::vector<FailedEpisode>{};
  const std::string shard = o.shard_count > 1 ? " --shard " + std::to_string(o.shard_index) + "/" +
                                                    std::to_string(o.shard_count)
                                              : "";
  write_batch_report(records, o.out_dir, "plantsim batch: " + run.spec.name,
                     "plantsim batch " + scenario_path + " --out " + o.out_dir + shard +
                         plugins::command_line_plugin_arguments(),
                     o.figures ? &run.loaded.worlds : nullptr, run.spec.planners,
                     o.gate.applied_to(run.spec.gate), o.figures, made_by, failures, scenario_path,
                     o.accept_mixed_builds);
}

/// Whether an output file of the folder is newer than its report (written last): one a killed
/// run or a hand left there, which only a rewrite removes. The records, the episodes re-run alone
/// and this run's own files (a --junit report in the folder) are no report's.
bool stray_outputs(const RunOptions& o, std::filesystem::file_time_type report_written) {
  namespace fs = std::filesystem;
  std::error_code ec;
  auto newer = [&](const fs::path& p) { return fs::last_write_time(p, ec) > report_written; };
  for (const fs::directory_entry& e : fs::directory_iterator(o.out_dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name == ".plantsim.lock" || name == "episodes.jsonl" || name == "episodes" ||
        name == "report.html" || !is_batch_output_name(name) ||
        std::find(o.own_files.begin(), o.own_files.end(), name) != o.own_files.end())
      continue;
    if (newer(e.path())) return true;
    if (e.is_directory(ec) && !e.is_symlink(ec))
      for (const fs::directory_entry& f : fs::recursive_directory_iterator(e.path(), ec))
        if (newer(f.path())) return true;
  }
  return false;
}

/// The folder's report stands complete from its records, with the options asked now: every
/// run removes the outputs before its episodes and writes them last, so a summary.json there
/// was written over these very records (unless a run was killed after writing it, which leaves
/// nothing to append). The figures and the gate asked must be the ones it was made with.
bool outputs_current(const RunOptions& o) {
  namespace fs = std::filesystem;
  if (o.fresh || !fs::is_regular_file(o.out_dir + "/report.html")) return false;
  try {
    const std::string path = o.out_dir + "/summary.json";
    if (!fs::is_regular_file(fs::symlink_status(path))) return false;
    const json j = json::parse(util::read_input_file(path, 64u << 20));
    if (stray_outputs(o, fs::last_write_time(o.out_dir + "/report.html"))) return false;
    const bool figures = fs::exists(o.out_dir + "/chart_success.png");
    const bool mixed_accepted =
        j.contains("mixed_builds") && j["mixed_builds"].value("accepted", false);
    return figures == o.figures && !o.gate.min_success && !o.gate.statistic &&
           (!j.contains("mixed_builds") || mixed_accepted == o.accept_mixed_builds);
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

std::vector<std::string> read_episode_records(const std::string& dir) {
  return read_records(dir + "/episodes.jsonl");
}

BatchOutcome run_batch(const std::string& scenario_path, const RunOptions& o) {
  const auto began = std::chrono::steady_clock::now();
  // Everything that can be wrong is found before the first episode.
  BatchSpec spec = load_batch_spec(scenario_path);
  if (o.steering)
    for (NamedConfig& c : spec.controllers) c.name += "+" + o.steering.name;
  if (o.shard_count < 1 || o.shard_index < 0 || o.shard_index >= o.shard_count)
    throw std::invalid_argument("--shard i/n needs 0 <= i < n");
  const ScenarioWorlds loaded = load_scenario_worlds(spec);
  check_charger_offsets(spec, loaded.worlds);
  const std::vector<episode::EpisodeConfig> configs = episode_configs(spec);
  for (const worlds::World& w : loaded.worlds)
    for (const episode::EpisodeConfig& c : configs) episode::check_episode_work(w, c);
  const EpisodeSpace all(spec, loaded.names);
  const ScenarioIdentity scenario =
      scenario_identity(spec, loaded.contents, loaded.names, all.size());
  const std::vector<Episode> mine = all.shard(o.shard_index, o.shard_count);
  check_step_bound(scenario_path, spec, configs, mine);
  BatchOutcome outcome;
  outcome.gate = spec.gate;
  outcome.scenario_fingerprint = scenario.fingerprint;
  outcome.episodes = static_cast<std::int64_t>(mine.size());
  if (o.check_only) return outcome;

  make_output_folder(o);
  const util::FolderLock lock(o.out_dir);  // one batch per folder, or both run every episode
  check_batch_output_folder(o.out_dir, o.own_files);  // again, now that no other plantsim writes
  const std::string jsonl = o.out_dir + "/episodes.jsonl";
  remove_batch_temporaries(o.out_dir);
  // The report is written anew from every record at the end: no summary, chart or failure
  // figure of an earlier run stays beside it (with --fresh, nor do the records). A resume reads
  // the records back before: one that cannot read them leaves the earlier report where it was
  // (a hostile line once ran out of memory after the report was gone).
  if (o.fresh) remove_batch_outputs(o.out_dir, false);
  const std::set<std::string> done =
      resume(jsonl, o, all, scenario.fingerprint, outcome.malformed_lines_cut);
  std::vector<Episode> todo;
  for (const Episode& e : mine)
    if (!done.count(e.id)) todo.push_back(e);
  outcome.skipped = outcome.episodes - static_cast<std::int64_t>(todo.size());
  // A resume with nothing to run is no new run: rewriting the outputs gave them this build's
  // commit, a new date and "in 0.0 s", and the dashboard's trend counted a second run.
  if (todo.empty() && outcome.malformed_lines_cut == 0 && outputs_current(o)) {
    outcome.outputs_kept = true;
    return outcome;
  }
  if (!o.fresh) remove_batch_outputs(o.out_dir, true);
  ScenarioIdentity recorded = scenario;  // the records name their scenario from their folder
  recorded.file = scenario_path_for_records(scenario.file, o.out_dir);
  const RunContext run{spec, loaded, configs, recorded, o};
  run_episodes(run, todo, open_for_append(jsonl), jsonl, outcome);
  util::MadeBy made_by;
  made_by.duration_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  made_by.input = "scenario";
  made_by.input_hash = scenario.fingerprint;
  write_report(run, scenario_path, made_by);
  return outcome;
}

}  // namespace plantsim::batch
