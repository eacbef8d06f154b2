// summary.json of a batch folder, from the same records and verdicts as its report.
#include "batch/batch_summary.h"

#include <map>
#include <tuple>

#include "batch/navigation_tally.h"

namespace plantsim::batch {

using nlohmann::json;

std::string batch_verdict(const std::vector<ConfigurationVerdict>& verdicts) {
  bool gated = false, passed = true;
  for (const ConfigurationVerdict& v : verdicts)
    if (v.threshold) gated = true, passed = passed && v.passed;
  return !gated ? "not gated" : passed ? "passed" : "failed";
}

json batch_summary_json(const std::vector<std::string>& lines,
                        const std::vector<ConfigurationVerdict>& verdicts, const Gate& gate,
                        const std::string& title, const std::string& command) {
  std::int64_t episodes = 0, succeeded = 0, docked_not_ok = 0, docked_lost = 0;
  std::map<std::string, std::int64_t> by_reason;
  // Each configuration's navigation metrics, world by world and pooled over the worlds (a gate
  // that pools judges the configuration over every world).
  using Key = std::tuple<std::string, std::string, std::string, std::string>;
  std::map<Key, NavigationTally> navigation;
  for (const std::string& line : lines) {
    const json j = json::parse(line);
    ++episodes;
    for (const std::string& world : {j["world"].get<std::string>(), std::string(kAllWorlds)})
      navigation[{world, j["planner"], j["controller"], j["fault"]}].add(j);
    if (record_succeeded(j)) {
      ++succeeded;
      // Integrity: a success whose estimator did not end `ok` (summary.csv has it per
      // configuration).
      const std::string health = j.value("localization_status", std::string("ok"));
      docked_not_ok += health != "ok";
      docked_lost += health == "lost";
      continue;
    }
    const auto reason = j.find("failure");
    ++by_reason[reason != j.end() && reason->is_string() ? reason->get<std::string>()
                                                         : "unrecorded"];
  }
  json configurations = json::array();
  std::int64_t gated = 0, below = 0, not_cleared = 0;
  for (const ConfigurationVerdict& v : verdicts) {
    json c = {{"world", v.world},
              {"planner", v.planner},
              {"controller", v.controller},
              {"fault", v.fault},
              {"episodes", v.episodes},
              {"succeeded", v.succeeded},
              {"success_rate", v.success_rate},
              {"wilson_low", v.wilson_low},
              {"wilson_high", v.wilson_high},
              {"threshold", v.threshold ? json(*v.threshold) : json(nullptr)},
              {"passed", v.passed},
              {"lower_bound_clears", v.lower_bound_clears()}};
    c.update(navigation[{v.world, v.planner, v.controller, v.fault}].json());
    configurations.push_back(std::move(c));
    if (!v.threshold) continue;
    ++gated;
    below += !v.passed;
    not_cleared += !v.lower_bound_clears();
  }
  return {{"title", title},
          {"command", command},
          {"verdict", batch_verdict(verdicts)},
          {"episodes", episodes},
          {"succeeded", succeeded},
          {"succeeded_not_ok", docked_not_ok},
          {"succeeded_lost", docked_lost},
          {"failures_by_reason", by_reason},
          {"gate",
           {{"statistic", statistic_name(gate.statistic)},
            {"pooled_over_worlds", gate.pool_worlds},
            {"gated_configurations", gated},
            {"below_threshold", below},
            {"lower_bound_below_threshold", not_cleared}}},
          {"configurations", configurations}};
}

}  // namespace plantsim::batch
