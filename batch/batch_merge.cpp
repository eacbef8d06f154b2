// Merging the shards of a batch (see the header): read the shards' records, find the scenario
// again, check the ids against it, write the joined records and the report.
#include "batch/batch_merge.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "batch/batch_report.h"
#include "batch/episode_record.h"
#include "batch/episode_records.h"
#include "batch/episode_space.h"
#include "batch/record_paths.h"
#include "batch/scenario_setup.h"
#include "episode/episode_json.h"
#include "util/atomic_file.h"
#include "util/folder_lock.h"

namespace plantsim::batch {
namespace {

using nlohmann::json;

/// The shards' records by id, of one scenario.
struct ShardRecords {
  std::map<std::string, std::pair<std::int64_t, std::string>> by_id;  // id -> (index, line)
  std::string fingerprint, first_dir, scenario_file;
  std::int64_t expected = 0;
  std::int64_t unkeyed = 0;  ///< records of builds before episode keys
};

/// The same episode from a run whose lists were ordered otherwise differs in its index and
/// scenario file only (and the build that ran it), and from any other run in its wall times (the
/// controller's compute time); anything else is a different result.
json result_of(const std::string& record) {
  json r = episode::without_wall_times(json::parse(record));
  r.erase("index"), r.erase("scenario_file"), r.erase("build");
  return r;
}

void add_record(ShardRecords& s, const std::string& dir, const std::string& path,
                std::string&& shard_line) {
  // Held with the scenario's path absolute: the merged records name it from the merge's folder.
  std::string line = rebased_record(shard_line, dir, "");
  const json j = json::parse(line);
  const std::string theirs = j["scenario"].get<std::string>();
  if (s.fingerprint.empty()) {
    s.fingerprint = theirs, s.first_dir = dir;
    s.expected = j.value("scenario_episodes", std::int64_t{0});
    if (s.expected > kMaxEpisodes)  // a merge holds every record in memory
      throw std::invalid_argument("merge: the scenario makes " + std::to_string(s.expected) +
                                  " episodes; a merge holds at most " +
                                  std::to_string(kMaxEpisodes) +
                                  ": merge groups of shards with --allow-partial (docs/batch.md)");
    s.scenario_file = scenario_path_from_record(j.value("scenario_file", std::string()), dir);
  } else if (theirs != s.fingerprint) {
    throw std::invalid_argument("cannot merge episodes of different scenarios: " + s.first_dir +
                                " holds scenario " + s.fingerprint + ", " + dir + " holds " +
                                theirs);
  }
  const std::string id = j["id"].get<std::string>();
  const std::int64_t index = j["index"].get<std::int64_t>();
  if (!j.contains("key"))
    ++s.unkeyed;
  else if (!j["key"].is_string() || j["key"].get<std::string>() != episode_key(theirs, id))
    throw std::invalid_argument("merge: " + path + " holds episode '" + id +
                                "' whose key does not match its scenario and id: a record of "
                                "another run, or one edited; merge only what batches wrote");
  if (index < 0 || index >= s.expected)
    throw std::invalid_argument("merge: " + path + " holds episode '" + id + "' with index " +
                                std::to_string(index) + ", outside the scenario's " +
                                std::to_string(s.expected) + " episodes");
  const auto [at, fresh] = s.by_id.try_emplace(id, index, line);
  if (!fresh && at->second.second != line && result_of(at->second.second) != result_of(line))
    throw std::invalid_argument("merge: episode '" + id +
                                "' appears twice with different results (" + path +
                                " and an earlier folder); shards of one batch never disagree: "
                                "merge each run's shards apart");
}

ShardRecords read_shards(const std::vector<std::string>& dirs) {
  ShardRecords s;
  for (const std::string& d : dirs) {
    const std::string path = d + "/episodes.jsonl";
    if (!std::filesystem::exists(std::filesystem::symlink_status(path)))
      throw std::invalid_argument(d + ": no episodes.jsonl to merge");
    const JsonlScan scan =
        scan_jsonl(path, [&](std::string&& line) { add_record(s, d, path, std::move(line)); });
    if (scan.bad_lines > 0)
      std::fprintf(stderr, "merge: warning: %s has %lld malformed line(s), left out (%s)\n",
                   path.c_str(), static_cast<long long>(scan.bad_lines),
                   scan.first_problem.c_str());
  }
  if (s.by_id.empty())
    throw std::invalid_argument("nothing to merge: the folders hold no episodes");
  return s;
}

/// The scenario the records name, when its file is still there and unchanged: the figures need
/// its worlds, and the ids are checked against its own.
struct MergedScenario {
  std::vector<worlds::World> worlds;
  std::vector<std::string> planners;
  Gate gate;
  std::optional<BatchSpec> spec;
  std::optional<EpisodeSpace> episodes;  // over *spec
};

void find_scenario(const ShardRecords& s, const std::string& given, MergedScenario& out) {
  if (!given.empty()) {  // named by the user: it must load and be the records' scenario
    BatchSpec spec = load_batch_spec(given);
    ScenarioWorlds loaded = load_scenario_worlds(spec);
    const std::string fingerprint =
        scenario_identity(spec, loaded.contents, loaded.names, s.expected).fingerprint;
    if (fingerprint != s.fingerprint)
      throw std::invalid_argument("merge: --scenario " + given + " is scenario " + fingerprint +
                                  " by its content; the records are of scenario " + s.fingerprint);
    out.worlds = std::move(loaded.worlds);
    out.planners = spec.planners;
    out.gate = spec.gate;
    out.spec = std::move(spec);
    out.episodes.emplace(*out.spec, loaded.names);
    return;
  }
  std::error_code ec;
  if (s.scenario_file.empty() || !std::filesystem::exists(s.scenario_file, ec)) return;
  try {
    BatchSpec spec = load_batch_spec(s.scenario_file);
    ScenarioWorlds loaded = load_scenario_worlds(spec);
    if (scenario_identity(spec, loaded.contents, loaded.names, s.expected).fingerprint ==
        s.fingerprint) {
      out.worlds = std::move(loaded.worlds);
      out.planners = spec.planners;
      out.gate = spec.gate;
      out.spec = std::move(spec);
      out.episodes.emplace(*out.spec, loaded.names);
    }
  } catch (const std::exception&) {
    out.worlds.clear();
    out.episodes.reset();
  }
}

/// Without the scenario file the records still tell its episodes: every id is world | planner |
/// controller | fault | seed, and a scenario runs every combination of its lists. More
/// combinations of the parts the records name than the scenario's episodes means a record of
/// another run stands among them (a foreign id counted in place of a missing one).
void check_ids_by_their_parts(const ShardRecords& s) {
  std::array<std::set<std::string>, 5> parts;
  for (const auto& [id, entry] : s.by_id) {
    std::size_t begin = 0;
    for (std::size_t k = 0; k < parts.size(); ++k) {
      const std::size_t end = k + 1 < parts.size() ? id.find('|', begin) : id.size();
      if (end == std::string::npos)
        throw std::invalid_argument("merge: episode '" + id + "' is not an id a batch writes");
      parts[k].insert(id.substr(begin, end - begin));
      begin = end + 1;
    }
  }
  double combinations = 1;
  for (const auto& p : parts) combinations *= static_cast<double>(p.size());
  if (combinations > static_cast<double>(s.expected))
    throw std::invalid_argument(
        "merge: the records name " + std::to_string(static_cast<long long>(combinations)) +
        " combinations of world, planner, controller, fault and seed, more than the scenario's " +
        std::to_string(s.expected) + " episodes: a record of another run stands among them");
}

/// Refuses a record foreign to the scenario, and missing episodes unless `allow_partial`.
void check_against_scenario(const ShardRecords& s, const MergedScenario& scenario,
                            bool allow_partial) {
  if (!scenario.episodes) {
    if (s.unkeyed > 0)
      throw std::invalid_argument(
          "merge: the scenario file " + s.scenario_file + " is gone or changed, and " +
          std::to_string(s.unkeyed) +
          " record(s) carry no episode key (an older build): nothing can tell them from records "
          "of another run; give the scenario with --scenario FILE");
    check_ids_by_their_parts(s);
  }
  if (scenario.episodes)
    for (const auto& [id, entry] : s.by_id)
      if (!scenario.episodes->find(id))
        throw std::invalid_argument("merge: episode '" + id +
                                    "' is not one of the scenario's episodes (" + s.scenario_file +
                                    "): a record of another run");
  if (scenario.worlds.empty())
    std::fprintf(
        stderr,
        "merge: note: the scenario file %s is gone or changed; the report has no plan figures\n",
        s.scenario_file.c_str());
  const auto merged = static_cast<std::int64_t>(s.by_id.size());
  if (merged >= s.expected || allow_partial) return;
  std::string missing;
  int named = 0;
  for (std::int64_t i = 0; scenario.episodes && i < scenario.episodes->size() && named < 5; ++i)
    if (const std::string id = scenario.episodes->at(i).id; !s.by_id.count(id))
      missing += (named++ ? ", " : " (") + id;
  if (named > 0) missing += s.expected - merged > named ? ", ...)" : ")";
  throw IncompleteBatch("merge: " + std::to_string(s.expected - merged) + " of the scenario's " +
                        std::to_string(s.expected) + " episodes are missing" + missing +
                        " (a shard not run or not finished?); rerun them, or pass --allow-partial");
}

}  // namespace

MergeOutcome merge_batches(const std::vector<std::string>& dirs, const std::string& out_dir,
                           const MergeOptions& options) {
  const auto began = std::chrono::steady_clock::now();
  // Before any work: never a user's folder, never through a link.
  check_batch_output_folder(out_dir, options.own_files);
  const ShardRecords shards = read_shards(dirs);
  MergedScenario scenario;
  find_scenario(shards, options.scenario, scenario);
  check_against_scenario(shards, scenario, options.allow_partial);
  std::vector<std::pair<std::int64_t, std::string>> ordered;
  for (const auto& [id, entry] : shards.by_id) ordered.push_back(entry);
  std::sort(ordered.begin(), ordered.end());
  std::string text;
  std::vector<std::string> lines;
  for (const auto& [index, held] : ordered) {
    const std::string line = rebased_record(held, "", out_dir);
    text += line + "\n";
    lines.push_back(line);
  }
  MergeOutcome outcome;
  outcome.gate = scenario.gate;
  outcome.episodes = static_cast<std::int64_t>(shards.by_id.size());
  outcome.expected = shards.expected;
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec || !std::filesystem::is_directory(out_dir))
    throw std::invalid_argument("cannot create output folder '" + out_dir + "'");
  const util::FolderLock lock(out_dir);
  remove_batch_temporaries(out_dir);
  remove_batch_outputs(out_dir, true);  // no figure of an earlier merge beside this one's
  util::write_file_atomically(out_dir + "/episodes.jsonl", text);
  util::MadeBy made_by;
  made_by.duration_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  made_by.input = "scenario";
  made_by.input_hash = shards.fingerprint;
  std::string command = "plantsim merge";
  for (const auto& d : dirs) command += " " + d;
  write_batch_report(
      lines, out_dir, "plantsim merge",
      command + " --out " + out_dir + (options.allow_partial ? " --allow-partial" : "") +
          (options.accept_mixed_builds ? " --accept-mixed-builds" : ""),
      scenario.worlds.empty() ? nullptr : &scenario.worlds, scenario.planners,
      options.gate.applied_to(outcome.gate), true, made_by, {}, "", options.accept_mixed_builds);
  return outcome;
}

}  // namespace plantsim::batch
