// The batch as a gate: each configuration (world x planner x controller x fault) judged
// against its success threshold, so CI can fail a change that makes docking worse, and a
// JUnit XML report in which each configuration is one test case.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "batch/batch_spec.h"

namespace plantsim::batch {

/// An episode record's success: docked at the charger, or, in a pursuit world, the target caught
/// (records written before the "succeeded" field count "docked").
bool record_succeeded(const nlohmann::json& record);
/// True for a record of a pursuit world (its goal is a target to catch, not the charger).
bool record_is_pursuit(const nlohmann::json& record);

/// An episode that did not succeed, as its record says: its id and why (the failure reason, or
/// the status when it has none).
struct GateFailure {
  std::string id, reason;
};

struct ConfigurationVerdict {
  std::string world, planner, controller, fault;
  std::vector<GateFailure> failed;  ///< in the records' order
  std::int64_t episodes = 0, succeeded = 0;
  bool pursuit = false;  ///< a pursuit world: success is "caught"
  const char* outcome() const { return pursuit ? "caught" : "docked"; }
  double success_rate = 0, wilson_low = 0, wilson_high = 0;
  std::optional<double> threshold;  ///< none: not gated
  bool passed = true;
  /// The 95 % Wilson lower bound clears the threshold: the verdict holds beyond sampling luck.
  bool lower_bound_clears() const { return threshold && wilson_low >= *threshold; }
  std::string name() const { return world + " / " + planner + " / " + controller + " / " + fault; }
};

/// "success_rate" or "wilson_low", as scenarios name them.
const char* statistic_name(GateStatistic s);

/// One verdict per configuration in the records, in the summary's order. `gate` from the
/// scenario; `min_success` (the command line's --min-success) replaces its default threshold.
std::vector<ConfigurationVerdict> judge_configurations(const std::vector<std::string>& jsonl_lines,
                                                       const Gate& gate);

/// "FAIL world_N50 / vg / default / wet: 41/50 docked, success_rate 0.820 < 0.900" per failure
/// ("caught" in a pursuit world).
std::string gate_failures_text(const std::vector<ConfigurationVerdict>& verdicts,
                               GateStatistic statistic);

/// The command that re-runs one episode alone into `out_dir`/episodes/, with its report and
/// replay, quoted for the shell (names may hold anything).
std::string episode_rerun_command(const std::string& scenario_path, const std::string& id,
                                  const std::string& out_dir = "DIR");

/// Where JUnit's failures point a reader: the scenario and the batch folder, for the command
/// that re-runs each failed episode with its replay (empty: the command is left out).
struct JunitContext {
  std::string scenario_path, folder;
};

/// JUnit XML (one testsuite, one testcase per configuration, <failure> when below threshold,
/// its text listing the failed episodes with their reasons and how to replay each);
/// `suite_properties` (the build's stamp) as the testsuite's <properties>.
std::string junit_xml(const std::string& suite_name,
                      const std::vector<ConfigurationVerdict>& verdicts, GateStatistic statistic,
                      const std::vector<std::pair<std::string, std::string>>& suite_properties = {},
                      const JunitContext& context = {});

/// Whether a file's first bytes are a JUnit report as junit_xml writes them.
bool looks_like_junit_report(const std::string& head);

/// Text made safe inside JUnit XML's attributes and elements, as junit_xml escapes it (for other
/// JUnit writers: plantsim diff).
std::string junit_text(const std::string& s);

}  // namespace plantsim::batch
