// A batch folder's verdict as data, summary.json: episodes and successes, failures by reason,
// each configuration's success with its Wilson interval, its threshold, the point verdict and
// whether the interval's lower bound clears the threshold, and the batch's verdict. The
// dashboard (plantsim summarize --html) reads it; so can CI scripts.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "batch/batch_gate.h"

namespace plantsim::batch {

/// "passed" (every gated configuration at or above its threshold), "failed", or "not gated".
std::string batch_verdict(const std::vector<ConfigurationVerdict>& verdicts);

nlohmann::json batch_summary_json(const std::vector<std::string>& jsonl_lines,
                                  const std::vector<ConfigurationVerdict>& verdicts,
                                  const Gate& gate, const std::string& title,
                                  const std::string& command);

}  // namespace plantsim::batch
