// The CSV tables of a batch's episode records: one row per configuration (summary.csv), and one
// per value of a swept fault parameter (sweep.csv).
#pragma once

#include <string>
#include <vector>

#include "batch/batch_spec.h"

namespace plantsim::batch {

/// Per-configuration summary (CSV text) of JSONL episode records: a field is empty where there is
/// no value (errors over no docked episode). With `gate`, three more columns per row: the gate's
/// statistic, its threshold and the verdict.
std::string summary_csv(const std::vector<std::string>& jsonl_lines, const Gate* gate = nullptr);

/// One row per value of a swept fault parameter, over every world, planner and controller
/// (CSV text); empty when the records come from no sweep.
std::string sweep_csv(const std::vector<std::string>& jsonl_lines);

}  // namespace plantsim::batch
