// The CSV tables of a batch's episode records: one row per configuration (summary.csv), and one
// per value of a swept fault parameter (sweep.csv).
#pragma once

#include <string>
#include <vector>

namespace plantsim::batch {

/// Per-configuration summary (CSV text) of JSONL episode records.
std::string summary_csv(const std::vector<std::string>& jsonl_lines);

/// One row per value of a swept fault parameter, over every world, planner and controller
/// (CSV text); empty when the records come from no sweep.
std::string sweep_csv(const std::vector<std::string>& jsonl_lines);

}  // namespace plantsim::batch
