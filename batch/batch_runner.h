// Running a batch: episodes spread over all cores, one JSON line per episode appended and
// flushed as it finishes, a killed run resumed without redoing or losing finished episodes,
// deterministic shards (--shard i/n) that merge into exactly what one run writes
// (batch_merge.h), a CSV summary per configuration (summary_tables.h) and an HTML report
// (batch_report.h).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/batch_spec.h"
#include "episode/run_episode.h"

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
  episode::EpisodeSteering steering;
  /// Further files of this run in the output folder (a --junit report written there).
  std::vector<std::string> own_files;
  /// A resume's records of more than one build: the verdict is not green unless accepted.
  bool accept_mixed_builds = false;
};

/// A batch stopped by its steering's `interrupted` poll (episode::EpisodeSteering): the episodes
/// finished before it are on disk, the next run resumes from them.
class BatchInterrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct BatchOutcome {
  std::int64_t episodes = 0, ran = 0, skipped = 0, succeeded = 0,
               collisions = 0;           ///< succeeded: docked or caught
  std::int64_t malformed_lines_cut = 0;  ///< resume found lines it could not use; rerun
  /// A resume that ran nothing and changed no record: the outputs of the run that made them
  /// stand as they were (no new date, commit or duration; no new trend point).
  bool outputs_kept = false;
  Gate gate;  ///< the scenario's gate
  std::string scenario_fingerprint;
};

/// Throws worlds::WorldError / std::invalid_argument on bad input before any episode runs.
BatchOutcome run_batch(const std::string& scenario_path, const RunOptions& options);

/// The complete, well-formed records of a batch folder's episodes.jsonl.
std::vector<std::string> read_episode_records(const std::string& dir);

}  // namespace plantsim::batch
