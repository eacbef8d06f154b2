// plantsim diff's comparison of two batch folders (a baseline and a candidate): their records
// paired by episode id, the episodes gained and lost, per configuration (world x planner x
// controller x fault, as the gate groups them) McNemar's exact test of success and the paired
// differences of time and position error on the episodes both sides succeeded in, and the
// verdict by a rule fixed before any measuring (docs/batch.md, "Did my change make it worse?").
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "batch/paired_tests.h"

namespace plantsim::batch {

/// The rule's practical margins: a time or error change smaller than these is no change, however
/// sure the interval. Time: 5 % of the baseline's mean time on the pairs compared; position
/// error: 2 mm (a tenth of the docking tolerance).
inline constexpr double kDiffTimeMargin = 0.05;
inline constexpr double kDiffErrorMarginM = 0.002;

enum class DiffVerdict { kNoChange, kBetter, kWorse };

/// "no detectable change", "better", "worse".
const char* diff_verdict_name(DiffVerdict v);

/// What the diff reads of one side's record of an episode.
struct DiffSide {
  bool succeeded = false;
  std::string status;
  std::string reason;  ///< the failure reason (the status when none), empty on success
  std::string detail;  ///< the failure's detail, if any
  double time_s = 0, position_error_m = 0;
  bool error_measured = true;
  std::string scenario_file;  ///< as the record names it (for the re-run command)
};

/// An episode that succeeded on one side only.
struct ChangedEpisode {
  std::string id, configuration;
  std::uint64_t seed = 0;
  bool gained = false;  ///< failed in the baseline, succeeded in the candidate; else lost
  DiffSide baseline, candidate;
};

/// Time or position error: candidate minus baseline on the pairs both sides succeeded in.
struct MetricDiff {
  PairedDifference difference;
  double baseline_mean = 0;
  double margin = 0;  ///< the practical margin, in the metric's unit
  DiffVerdict verdict = DiffVerdict::kNoChange;
};

struct ConfigurationDiff {
  std::string world, planner, controller, fault;
  std::int64_t pairs = 0, baseline_succeeded = 0, candidate_succeeded = 0, gained = 0, lost = 0;
  double mcnemar_p = 1;
  DiffVerdict success = DiffVerdict::kNoChange;
  MetricDiff time, error;  ///< time_s (s) and position_error_m (m)
  DiffVerdict verdict = DiffVerdict::kNoChange;
  std::vector<std::string> why;  ///< the rule's findings, one sentence each
  std::string name() const { return world + " / " + planner + " / " + controller + " / " + fault; }
};

/// A side's folder: its records and the build its summary.json says made them.
struct DiffFolder {
  std::string folder;
  std::int64_t records = 0;
  std::vector<std::string> scenarios;  ///< the records' scenario fingerprints
  nlohmann::ordered_json made_by;      ///< summary.json's "made_by", null when none
};

struct BatchDiff {
  double level = 0.05;
  DiffFolder baseline, candidate;
  std::int64_t paired = 0, gained = 0, lost = 0;
  std::int64_t only_baseline = 0, only_candidate = 0;
  std::vector<std::string> only_baseline_ids, only_candidate_ids;  ///< the first few
  std::vector<ChangedEpisode> changed;                             ///< by configuration, then id
  std::vector<ConfigurationDiff> configurations;
  double pooled_mcnemar_p = 1;  ///< all configurations pooled: said, not judged
  DiffVerdict verdict = DiffVerdict::kNoChange;
  std::string input_hash;  ///< a fingerprint of both sides' paired records
};

/// Reads both folders and compares them. Throws std::invalid_argument naming the folder or file
/// (a missing folder, no episodes.jsonl, a malformed or torn line, a record whose key is not its
/// own, one episode twice with different results, no records, no episode in both) before
/// anything is written.
BatchDiff diff_batches(const std::string& baseline_dir, const std::string& candidate_dir,
                       double level);

}  // namespace plantsim::batch
