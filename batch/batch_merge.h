// Merging the shards of a batch: their episodes.jsonl joined into one folder, exactly what one
// run of the whole scenario writes, with the summary, report and figures made again. Refuses
// records of different scenarios, a record foreign to the scenario, one episode with two results,
// and (unless asked) missing episodes.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/batch_spec.h"

namespace plantsim::batch {

struct MergeOptions {
  bool allow_partial = false;  ///< merge even when episodes of the scenario are missing
  /// The scenario file, when it no longer stands where the records say (moved, or another
  /// checkout): it must be the records' scenario by content (its fingerprint), whatever its path.
  std::string scenario;
  std::vector<std::string> own_files;  ///< further files of this merge in its output folder
  GateOverride gate;
  /// Shards run by different builds: the report's verdict is not green unless accepted.
  bool accept_mixed_builds = false;
};

struct MergeOutcome {
  std::int64_t episodes = 0, expected = 0;
  Gate gate;  ///< the scenario's gate, when its file could be read again (else none)
};

/// A merge that would lose episodes (shards missing): refused like any other input that cannot
/// make the batch, exit 2, naming the first missing ids.
struct IncompleteBatch : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// Joins the episodes.jsonl of shard folders (duplicates by id dropped) into out_dir, with the
/// summary, report and figures recomputed. Refuses (std::invalid_argument) records of different
/// scenarios or without a scenario fingerprint; throws IncompleteBatch when episodes are missing
/// unless options.allow_partial.
MergeOutcome merge_batches(const std::vector<std::string>& dirs, const std::string& out_dir,
                           const MergeOptions& options = {});

}  // namespace plantsim::batch
