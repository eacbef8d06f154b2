// `plantsim tune`: the default settings judged on the tuning episodes, NLopt's search and random
// search with the same budget on the same episodes, then the default and each search's best
// proven on the held-out validation episodes, paired, and the report written.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tune/evaluation_log.h"
#include "tune/paired_test.h"
#include "tune/tune_spec.h"

namespace plantsim::tune {

struct TuneOptions {
  std::string out_dir;
  bool fresh = false;       ///< discard the folder's earlier evaluations instead of resuming
  bool check_only = false;  ///< check everything, count the episodes, run nothing
  bool progress = true;     ///< one line per evaluation on stderr
  bool figures = true;
  std::string
      command;  ///< the command line that makes it again, quoted for the shell (the report's)
  std::function<bool()> interrupted;  ///< polled between episodes (Python's Ctrl-C)
  /// Shard i of n (n > 1): the default, then shard 0 NLopt's search and shards 1..n-1 every
  /// (n-1)th of random search's points; no validation and no report (docs/tune.md, Slurm).
  int shard_index = 0, shard_count = 1;
  /// Folders of this tuning's shards whose evaluations are read in before the searches ask.
  std::vector<std::string> merge_dirs;
};

/// One setting proven on the validation episodes.
struct Proven {
  std::string name;  ///< "default", "nlopt", "random"
  Evaluation tuning, validation;
};

struct TuneOutcome {
  std::int64_t tuning_episodes = 0, validation_episodes = 0;
  int evaluations_run = 0, evaluations_reused = 0;
  int evaluations_merged = 0;  ///< taken from the shards' folders
  double floor = 0;            ///< the constrained objectives' Wilson floor on the tuning episodes
  std::vector<Evaluation> history;        ///< default, then NLopt's, then random search's
  std::vector<Proven> proven;             ///< default, nlopt, random (none for a shard)
  std::string best;                       ///< which search's setting best.json holds
  PairedComparison best_against_default;  ///< on the validation episodes
  std::string fingerprint;
};

/// Throws std::invalid_argument / worlds::WorldError on bad input before any episode runs.
TuneOutcome run_tune(const TuneSpec& spec, const TuneOptions& options);

/// The files a tuning writes into its folder (anything else there is refused).
const std::vector<std::string>& tune_output_names();

}  // namespace plantsim::tune
