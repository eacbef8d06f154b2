// Running a batch: episodes spread over all cores, one JSON line per episode appended and
// flushed as it finishes, a killed run resumed without redoing or losing finished episodes,
// deterministic shards (--shard i/n) that merge into exactly what one run writes, a CSV
// summary per configuration and an HTML report.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/batch_spec.h"

namespace plantsim::batch {

struct RunOptions {
  std::string out_dir;
  bool fresh = false;  ///< discard the folder's earlier episodes instead of resuming
  bool check_only =
      false;  ///< validate everything and count the episodes; run nothing, write nothing
  int shard_index = 0;
  int shard_count = 1;
  int threads = 0;       ///< 0: one per core
  bool progress = true;  ///< progress bar with rate and ETA on stderr
  bool figures = true;   ///< comparison figures in the report
  GateOverride gate;  ///< the command line's changes to the scenario's gate (drawn in the charts)
  /// An outside controller for every episode (the Python module's); its name joins each
  /// controller's, so the ids and the scenario's fingerprint tell its episodes apart.
  sim::EpisodeSteering steering;
  /// Further files of this run in the output folder (a --junit report written there).
  std::vector<std::string> own_files;
};

struct BatchOutcome {
  std::int64_t episodes = 0, ran = 0, skipped = 0, succeeded = 0,
               collisions = 0;           ///< succeeded: docked or caught
  std::int64_t malformed_lines_cut = 0;  ///< resume found lines it could not use; rerun
  Gate gate;                             ///< the scenario's gate
  std::string scenario_fingerprint;
};

struct MergeOptions {
  bool allow_partial = false;          ///< merge even when episodes of the scenario are missing
  std::vector<std::string> own_files;  ///< further files of this merge in its output folder
  GateOverride gate;
};

struct MergeOutcome {
  std::int64_t episodes = 0, expected = 0;
  Gate gate;  ///< the scenario's gate, when its file could be read again (else none)
};

/// A merge that would lose episodes: shards missing (exit 1, not bad input).
struct IncompleteBatch : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Throws worlds::WorldError / std::invalid_argument on bad input before any episode runs.
BatchOutcome run_batch(const std::string& scenario_path, const RunOptions& options);

/// Joins the episodes.jsonl of shard folders (duplicates by id dropped) into out_dir, with the
/// summary, report and figures recomputed. Refuses (std::invalid_argument) records of different
/// scenarios or without a scenario fingerprint; throws IncompleteBatch when episodes are missing
/// unless options.allow_partial.
MergeOutcome merge_batches(const std::vector<std::string>& dirs, const std::string& out_dir,
                           const MergeOptions& options = {});

/// The complete, well-formed records of a batch folder's episodes.jsonl.
std::vector<std::string> read_episode_records(const std::string& dir);

/// Per-configuration summary (CSV text) of JSONL episode records.
std::string summary_csv(const std::vector<std::string>& jsonl_lines);

/// One row per value of a swept fault parameter, over every world, planner and controller
/// (CSV text); empty when the records come from no sweep.
std::string sweep_csv(const std::vector<std::string>& jsonl_lines);

/// One episode of a scenario run again on its own, exactly as the batch ran it (its start,
/// faults and seed come from the scenario and the episode's id).
struct ReplayedEpisode {
  std::string id;
  worlds::World plant;
  sim::EpisodeResult result;
  sim::EpisodeConfig config;
};
using FailedEpisode = ReplayedEpisode;

/// Failed episodes a batch report draws (replayed, each with its run figure).
inline constexpr std::size_t kGalleryEpisodes = 12;

/// Throws std::invalid_argument naming the scenario when it has no episode `id`.
ReplayedEpisode replay_batch_episode(const std::string& scenario_path, const std::string& id);

/// Wilson score interval for k successes in n trials (95 %: z = 1.96).
std::pair<double, double> wilson_interval(std::int64_t k, std::int64_t n, double z = 1.96);

}  // namespace plantsim::batch
