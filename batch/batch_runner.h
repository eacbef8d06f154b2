// Running a batch: episodes spread over all cores, one JSON line per episode appended and
// flushed as it finishes, a killed run resumed without redoing or losing finished episodes,
// deterministic shards (--shard i/n) that merge into exactly what one run writes, a CSV
// summary per configuration and an HTML report.
#pragma once

#include <string>
#include <vector>

#include "batch/batch_spec.h"

namespace plantsim::batch {

struct RunOptions {
  std::string out_dir;
  int shard_index = 0;
  int shard_count = 1;
  int threads = 0;        ///< 0: one per core
  bool progress = true;   ///< progress bar with rate and ETA on stderr
  bool figures = true;    ///< comparison figures in the report
};

struct BatchOutcome {
  std::int64_t episodes = 0, ran = 0, skipped = 0, docked = 0, collisions = 0;
};

/// Throws worlds::WorldError / std::invalid_argument on bad input before any episode runs.
BatchOutcome run_batch(const std::string& scenario_path, const RunOptions& options);

/// Joins the episodes.jsonl of shard folders (duplicates by id dropped) into out_dir, with the
/// summary and report recomputed. Returns the number of episodes.
std::int64_t merge_batches(const std::vector<std::string>& dirs, const std::string& out_dir);

/// Per-configuration summary (CSV text) of JSONL episode records.
std::string summary_csv(const std::vector<std::string>& jsonl_lines);

/// One row per value of a swept fault parameter, over every world, planner and controller
/// (CSV text); empty when the records come from no sweep.
std::string sweep_csv(const std::vector<std::string>& jsonl_lines);

/// Wilson score interval for k successes in n trials (95 %: z = 1.96).
std::pair<double, double> wilson_interval(std::int64_t k, std::int64_t n, double z = 1.96);

}  // namespace plantsim::batch
