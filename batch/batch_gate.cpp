// Gate verdicts and the JUnit report.
#include "batch/batch_gate.h"

#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "batch/wilson_interval.h"
#include "plugins/plugin_loader.h"
#include "render/report.h"
#include "util/fixed_text.h"
#include "util/shell_word.h"
#include "worlds/names.h"

namespace plantsim::batch {
const char* statistic_name(GateStatistic s) {
  switch (s) {  // a new statistic without its name does not compile (-Wswitch, -Werror)
    case GateStatistic::kWilsonLow:
      return "wilson_low";
    case GateStatistic::kSuccessRate:
      return "success_rate";
  }
  return "unknown";
}

namespace {

bool matches(const GateRule& r, const ConfigurationVerdict& v) {
  return (r.world.empty() || r.world == v.world || v.world == kAllWorlds) &&
         (r.planner.empty() || r.planner == v.planner) &&
         (r.controller.empty() || r.controller == v.controller) &&
         (r.fault.empty() || r.fault == v.fault);
}

// HTML's escapes, then what XML also escapes in attributes, and no control characters but tab
// and newline, nor the non-characters U+FFFE and U+FFFF (XML 1.0 refuses them all).
std::string xml_escaped(const std::string& s) {
  std::string out;
  const std::string html = render::html_escape(s);
  for (std::size_t i = 0; i < html.size(); ++i) {
    const char c = html[i];
    const auto u = static_cast<unsigned char>(c);
    if (u == 0xEF && i + 2 < html.size() && static_cast<unsigned char>(html[i + 1]) == 0xBF &&
        (static_cast<unsigned char>(html[i + 2]) & 0xFE) == 0xBE) {
      out += '?';  // EF BF BE and EF BF BF: U+FFFE, U+FFFF
      i += 2;
    } else if (c == '\'') {
      out += "&apos;";
    } else {
      out += u < 0x20 && c != '\n' && c != '\t' ? '?' : c;
    }
  }
  return out;
}

using util::fixed;

std::string verdict_line(const ConfigurationVerdict& v, GateStatistic statistic) {
  const double value = statistic == GateStatistic::kWilsonLow ? v.wilson_low : v.success_rate;
  return v.name() + ": " + std::to_string(v.succeeded) + "/" + std::to_string(v.episodes) + " " +
         v.outcome() + ", " + statistic_name(statistic) + " " + fixed(value) +
         (v.passed ? " >= " : " < ") + fixed(*v.threshold);
}

}  // namespace

bool record_succeeded(const nlohmann::json& record) {
  if (record.contains("succeeded") && record["succeeded"].is_boolean())
    return record["succeeded"].get<bool>();
  return record.value("docked", false);
}

bool record_is_pursuit(const nlohmann::json& record) {
  return record.value("goal", std::string("dock")) == "catch";
}

std::vector<ConfigurationVerdict> judge_configurations(const std::vector<std::string>& lines,
                                                       const Gate& gate) {
  std::map<std::tuple<std::string, std::string, std::string, std::string>, ConfigurationVerdict>
      by_key;
  for (const std::string& line : lines) {
    const nlohmann::json j = nlohmann::json::parse(line);
    const auto key =
        std::make_tuple(gate.pool_worlds ? std::string(kAllWorlds) : j.value("world", ""),
                        j.value("planner", ""), j.value("controller", ""), j.value("fault", ""));
    ConfigurationVerdict& v = by_key[key];
    std::tie(v.world, v.planner, v.controller, v.fault) = key;
    ++v.episodes;
    if (record_succeeded(j)) {
      ++v.succeeded;
    } else {
      const nlohmann::json& why = j.contains("failure") && j["failure"].is_string()
                                      ? j["failure"]
                                      : j.value("status", nlohmann::json("failed"));
      v.failed.push_back({j.value("id", std::string()),
                          why.is_string() ? why.get<std::string>() : std::string("failed")});
    }
    v.pursuit = v.pursuit || record_is_pursuit(j);
  }
  std::vector<ConfigurationVerdict> out;
  for (auto& [key, v] : by_key) {
    v.success_rate = static_cast<double>(v.succeeded) / static_cast<double>(v.episodes);
    std::tie(v.wilson_low, v.wilson_high) = wilson_interval(v.succeeded, v.episodes);
    v.threshold = gate.min_success;
    for (const GateRule& r : gate.rules)
      if (matches(r, v)) v.threshold = r.min_success;
    const double value =
        gate.statistic == GateStatistic::kWilsonLow ? v.wilson_low : v.success_rate;
    // A hair below the threshold from rounding (0.9 of 10 computed as 0.8999...) still passes.
    v.passed = !v.threshold || value >= *v.threshold - 1e-12;
    out.push_back(v);
  }
  return out;
}

std::string gate_failures_text(const std::vector<ConfigurationVerdict>& verdicts,
                               GateStatistic statistic) {
  std::string text;
  for (const ConfigurationVerdict& v : verdicts)
    if (!v.passed) text += "FAIL " + verdict_line(v, statistic) + "\n";
  return text;
}

std::string episode_rerun_command(const std::string& scenario_path, const std::string& id,
                                  const std::string& out_dir) {
  return "plantsim batch " + util::shell_word(scenario_path) + " --episode " +
         util::shell_word(id) + " --out " +
         (out_dir == "DIR" ? out_dir : util::shell_word(out_dir)) +
         plugins::command_line_plugin_arguments();
}

namespace {

/// A failure's text: every failed episode (up to a limit) with its reason, and how to replay it.
std::string failed_episodes_text(const ConfigurationVerdict& v, const JunitContext& context) {
  constexpr std::size_t kListed = 50;
  std::string text = std::to_string(v.failed.size()) + " failed episode(s):\n";
  for (std::size_t i = 0; i < v.failed.size() && i < kListed; ++i) {
    const GateFailure& f = v.failed[i];
    text += "  " + f.id + ": " + f.reason + "\n";
    if (!context.scenario_path.empty())
      text += "    replay: " + episode_rerun_command(context.scenario_path, f.id, context.folder) +
              "  (then " + context.folder + "/episodes/" + worlds::file_name_component(f.id) +
              "/report.html)\n";
  }
  if (v.failed.size() > kListed)
    text += "  ... and " + std::to_string(v.failed.size() - kListed) + " more (episodes.jsonl)\n";
  return text;
}

}  // namespace

std::string junit_xml(const std::string& suite_name,
                      const std::vector<ConfigurationVerdict>& verdicts, GateStatistic statistic,
                      const std::vector<std::pair<std::string, std::string>>& suite_properties,
                      const JunitContext& context) {
  int failures = 0;
  for (const ConfigurationVerdict& v : verdicts) failures += !v.passed;
  std::string xml =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n  <testsuite name=\"" +
      xml_escaped(suite_name) + "\" tests=\"" + std::to_string(verdicts.size()) + "\" failures=\"" +
      std::to_string(failures) + "\" errors=\"0\">\n";
  if (!suite_properties.empty()) {
    xml += "    <properties>";
    for (const auto& [name, value] : suite_properties)
      xml += "<property name=\"" + xml_escaped(name) + "\" value=\"" + xml_escaped(value) + "\"/>";
    xml += "</properties>\n";
  }
  for (const ConfigurationVerdict& v : verdicts) {
    xml += "    <testcase classname=\"" + xml_escaped(suite_name + "." + v.world) + "\" name=\"" +
           xml_escaped(v.planner + " / " + v.controller + " / " + v.fault) + "\">\n";
    xml +=
        "      <properties><property name=\"episodes\" value=\"" + std::to_string(v.episodes) +
        "\"/><property name=\"" + v.outcome() + "\" value=\"" + std::to_string(v.succeeded) +
        "\"/><property name=\"success_rate\" value=\"" + fixed(v.success_rate, 4) +
        "\"/><property name=\"wilson_low\" value=\"" + fixed(v.wilson_low, 4) + "\"/>" +
        (v.threshold ? "<property name=\"min_success\" value=\"" + fixed(*v.threshold, 4) + "\"/>"
                     : std::string()) +
        "</properties>\n";
    if (!v.passed)
      xml += "      <failure message=\"" + xml_escaped(verdict_line(v, statistic)) +
             "\" type=\"success_below_threshold\">" +
             xml_escaped(failed_episodes_text(v, context)) + "</failure>\n";
    else if (!v.threshold)
      xml += "      <system-out>" +
             xml_escaped(std::to_string(v.succeeded) + "/" + std::to_string(v.episodes) + " " +
                         v.outcome() + " (not gated)") +
             "</system-out>\n";
    xml += "    </testcase>\n";
  }
  return xml + "  </testsuite>\n</testsuites>\n";
}

bool looks_like_junit_report(const std::string& head) {
  return head.rfind("<?xml", 0) == 0 && head.find("<testsuites") != std::string::npos;
}

std::string junit_text(const std::string& s) { return xml_escaped(s); }

}  // namespace plantsim::batch
