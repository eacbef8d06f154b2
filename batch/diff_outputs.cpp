// diff.json, diff.md and the JUnit report of plantsim diff (diff.html: batch/diff_report.cpp).
#include "batch/diff_outputs.h"

#include <filesystem>
#include <map>

#include "batch/batch_gate.h"
#include "util/fixed_text.h"
#include "worlds/known_keys.h"

namespace plantsim::batch {
namespace {

using nlohmann::ordered_json;
using util::fixed;

ordered_json interval_json(const PairedDifference& p) {
  if (!p.interval) return nullptr;
  return ordered_json::array({p.interval->first, p.interval->second});
}

ordered_json metric_json(const MetricDiff& m, const std::string& unit) {
  ordered_json j;
  j["pairs"] = m.difference.pairs;
  j["baseline_mean_" + unit] = m.baseline_mean;
  j["mean_difference_" + unit] = m.difference.mean;
  j["sd_" + unit] = m.difference.sd;
  j["interval_" + unit] = interval_json(m.difference);
  j["margin_" + unit] = m.margin;
  j["verdict"] = diff_verdict_name(m.verdict);
  return j;
}

ordered_json folder_json(const DiffFolder& f) {
  return {{"folder", f.folder},
          {"records", f.records},
          {"scenarios", f.scenarios},
          {"made_by", f.made_by}};
}

ordered_json side_json(const DiffSide& s, const std::string& folder, const std::string& id) {
  ordered_json j;
  j["succeeded"] = s.succeeded;
  j["status"] = s.status;
  j["reason"] = s.reason.empty() ? ordered_json(nullptr) : ordered_json(s.reason);
  if (!s.detail.empty()) j["detail"] = s.detail;
  j["time_s"] = s.time_s;
  j["position_error_m"] = s.position_error_m;
  j["rerun"] = diff_rerun_command(s, folder, id);
  const std::string replay = diff_replay(folder, id);
  j["replay"] = replay.empty() ? ordered_json(nullptr)
                               : ordered_json((std::filesystem::path(folder) / replay).string());
  return j;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

/// "made by commit 1234567890ab (with uncommitted changes) on DATE", or what is not known.
std::string build_of(const DiffFolder& f) {
  if (!f.made_by.is_object()) return "its build unknown (no summary.json stamp)";
  const std::string commit = f.made_by.contains("commit") && f.made_by["commit"].is_string()
                                 ? f.made_by["commit"].get<std::string>()
                                 : "?";
  const bool dirty = f.made_by.contains("dirty") && f.made_by["dirty"].is_boolean() &&
                     f.made_by["dirty"].get<bool>();
  const std::string date = f.made_by.contains("date") && f.made_by["date"].is_string()
                               ? f.made_by["date"].get<std::string>()
                               : "?";
  return "made by commit " + commit + (dirty ? " with uncommitted changes" : "") + " on " + date;
}

std::string md_cell(std::string s) {
  std::string out;
  for (char c : s)
    out += c == '|' ? std::string("\\|") : c == '\n' ? std::string(" ") : std::string(1, c);
  return out;
}

std::string change_text(const MetricDiff& m, double scale, int digits) {
  if (m.difference.pairs == 0) return "-";
  std::string s = (m.difference.mean >= 0 ? "+" : "") + fixed(m.difference.mean * scale, digits);
  if (m.difference.interval)
    s += " (" + fixed(m.difference.interval->first * scale, digits) + " to " +
         fixed(m.difference.interval->second * scale, digits) + ")";
  return s;
}

std::string outcome_text(const DiffSide& s) {
  return s.succeeded ? s.status + ", " + fixed(s.time_s, 1) + " s"
                     : s.reason + (s.status != s.reason ? " (" + s.status + ")" : "") + " at " +
                           fixed(s.time_s, 1) + " s";
}

}  // namespace

std::string diff_rerun_command(const DiffSide& side, const std::string& folder,
                               const std::string& id) {
  return episode_rerun_command(side.scenario_file.empty() ? "SCENARIO" : side.scenario_file, id,
                               folder);
}

std::string diff_replay(const std::string& folder, const std::string& id) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const std::string component = worlds::file_name_component(id);
  const std::string own = "episodes/" + component + "/report.html";
  if (fs::is_regular_file(fs::path(folder) / own, ec)) return own;
  const fs::path gallery = fs::path(folder) / "failures";
  if (!fs::is_directory(gallery, ec)) return "";
  std::string found;
  for (const auto& e : fs::directory_iterator(gallery, ec)) {
    const std::string name = e.path().filename().string();
    const std::size_t underscore = name.find('_');
    if (underscore == std::string::npos || underscore == 0 ||
        name.find_first_not_of("0123456789") != underscore ||
        name.substr(underscore + 1) != component + ".html")
      continue;
    if (found.empty() || name < found) found = name;
  }
  return found.empty() ? "" : "failures/" + found;
}

ordered_json diff_json(const BatchDiff& d, const util::MadeBy& made_by,
                       const std::string& command) {
  ordered_json j;
  j["verdict"] = diff_verdict_name(d.verdict);
  j["level"] = d.level;
  j["rule"] = {
      {"success",
       "McNemar's exact two-sided test on the episodes one side succeeded in: p < level "
       "with more lost than gained is worse, more gained better"},
      {"time_and_position_error",
       "paired differences (candidate - baseline) on the episodes both succeeded in, with their "
       "(1 - level) Student t interval: the whole interval above 0 and the mean change beyond the "
       "margin is worse; below 0 and beyond the margin, better"},
      {"time_margin_of_baseline_mean", kDiffTimeMargin},
      {"position_error_margin_m", kDiffErrorMarginM},
      {"configuration", "worse when any test is worse, else better when any is better"},
      {"overall", "worse when any configuration is worse, else better when any is better"}};
  j["command"] = command;
  j["made_by"] = made_by.json();
  j["baseline"] = folder_json(d.baseline);
  j["candidate"] = folder_json(d.candidate);
  j["paired"] = d.paired;
  j["gained"] = d.gained;
  j["lost"] = d.lost;
  j["pooled_mcnemar_p"] = d.pooled_mcnemar_p;
  j["only_in_baseline"] = {{"count", d.only_baseline}, {"first_ids", d.only_baseline_ids}};
  j["only_in_candidate"] = {{"count", d.only_candidate}, {"first_ids", d.only_candidate_ids}};
  ordered_json configurations = ordered_json::array();
  for (const ConfigurationDiff& c : d.configurations) {
    ordered_json cj;
    cj["world"] = c.world, cj["planner"] = c.planner, cj["controller"] = c.controller;
    cj["fault"] = c.fault, cj["pairs"] = c.pairs;
    cj["baseline_succeeded"] = c.baseline_succeeded;
    cj["candidate_succeeded"] = c.candidate_succeeded;
    cj["lost"] = c.lost, cj["gained"] = c.gained, cj["mcnemar_p"] = c.mcnemar_p;
    cj["success_verdict"] = diff_verdict_name(c.success);
    cj["time"] = metric_json(c.time, "s");
    cj["position_error"] = metric_json(c.error, "m");
    cj["verdict"] = diff_verdict_name(c.verdict);
    cj["why"] = c.why;
    configurations.push_back(std::move(cj));
  }
  j["configurations"] = std::move(configurations);
  ordered_json changed = ordered_json::array();
  for (std::size_t i = 0; i < d.changed.size() && i < kDiffJsonChanged; ++i) {
    const ChangedEpisode& e = d.changed[i];
    changed.push_back({{"id", e.id},
                       {"configuration", e.configuration},
                       {"change", e.gained ? "gained" : "lost"},
                       {"baseline", side_json(e.baseline, d.baseline.folder, e.id)},
                       {"candidate", side_json(e.candidate, d.candidate.folder, e.id)}});
  }
  j["changed_listed"] = changed.size();
  j["changed"] = std::move(changed);
  return j;
}

std::string diff_markdown(const BatchDiff& d, const util::MadeBy& made_by,
                          const std::string& command) {
  std::string md = "# plantsim diff: " + upper(diff_verdict_name(d.verdict)) + "\n\n";
  md += made_by.text() + "\n\n`" + command + "`\n\n";
  md += "Baseline `" + d.baseline.folder + "` (" + std::to_string(d.baseline.records) +
        " records, " + build_of(d.baseline) + "); candidate `" + d.candidate.folder + "` (" +
        std::to_string(d.candidate.records) + " records, " + build_of(d.candidate) + ").\n\n";
  md += std::to_string(d.paired) + " episodes in both: " + std::to_string(d.lost) + " lost, " +
        std::to_string(d.gained) +
        " gained (all configurations pooled: McNemar exact p = " + fixed(d.pooled_mcnemar_p, 4) +
        ", said, not judged); level " + fixed(d.level, 3) + ".";
  if (d.only_baseline > 0)
    md += " " + std::to_string(d.only_baseline) + " episode(s) only in the baseline, not compared.";
  if (d.only_candidate > 0)
    md +=
        " " + std::to_string(d.only_candidate) + " episode(s) only in the candidate, not compared.";
  md +=
      "\n\n| configuration | verdict | episodes | baseline succeeded | candidate succeeded | lost "
      "| "
      "gained | McNemar p | time change s (interval) | position error change mm (interval) |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const ConfigurationDiff& c : d.configurations)
    md += "| " + md_cell(c.name()) + " | " + diff_verdict_name(c.verdict) + " | " +
          std::to_string(c.pairs) + " | " + std::to_string(c.baseline_succeeded) + " | " +
          std::to_string(c.candidate_succeeded) + " | " + std::to_string(c.lost) + " | " +
          std::to_string(c.gained) + " | " + fixed(c.mcnemar_p, 4) + " | " +
          change_text(c.time, 1, 2) + " | " + change_text(c.error, 1000, 2) + " |\n";
  std::string why;
  for (const ConfigurationDiff& c : d.configurations)
    for (const std::string& w : c.why) why += "- " + md_cell(c.name()) + ": " + w + "\n";
  if (!why.empty()) md += "\n## Why\n\n" + why;
  if (!d.changed.empty()) {
    md += "\n## Changed episodes (" + std::to_string(d.changed.size()) +
          (d.changed.size() > kDiffMarkdownChanged
               ? ", the first " + std::to_string(kDiffMarkdownChanged) + "; diff.json lists more"
               : std::string()) +
          ")\n\n| episode | change | baseline | candidate |\n|---|---|---|---|\n";
    for (std::size_t i = 0; i < d.changed.size() && i < kDiffMarkdownChanged; ++i) {
      const ChangedEpisode& e = d.changed[i];
      md += "| " + md_cell(e.id) + " | " + (e.gained ? "gained" : "lost") + " | " +
            md_cell(outcome_text(e.baseline)) + " | " + md_cell(outcome_text(e.candidate)) + " |\n";
    }
  }
  md +=
      "\n## The rule (docs/batch.md, \"Did my change make it worse?\")\n\n"
      "Per configuration, on the episodes both folders hold: success is worse when McNemar's "
      "exact two-sided test on the episodes one side succeeded in gives p < " +
      fixed(d.level, 3) +
      " with more lost than gained; time and position error (episodes both succeeded in) are "
      "worse when the whole " +
      fixed(100 * (1 - d.level), 0) +
      " % interval of the paired mean change lies above 0 and the mean change exceeds its "
      "margin (time: " +
      fixed(100 * kDiffTimeMargin, 0) +
      " % of the baseline's mean; position error: " + fixed(1000 * kDiffErrorMarginM, 0) +
      " mm); better is the mirror image. A configuration is worse when any test is, the diff "
      "when any configuration is.\n";
  return md;
}

std::string diff_junit(const BatchDiff& d, const util::MadeBy& made_by) {
  int failures = 0;
  for (const ConfigurationDiff& c : d.configurations) failures += c.verdict == DiffVerdict::kWorse;
  std::string xml =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n  <testsuite "
      "name=\"plantsim diff\" tests=\"" +
      std::to_string(d.configurations.size()) + "\" failures=\"" + std::to_string(failures) +
      "\" errors=\"0\">\n    <properties>";
  const ordered_json stamp = made_by.json();
  for (const auto& [key, value] : stamp.items())
    xml += "<property name=\"" +
           junit_text(key == "plantsim" ? "plantsim_version" : "plantsim_" + key) + "\" value=\"" +
           junit_text(value.is_string() ? value.get<std::string>() : value.dump()) + "\"/>";
  xml += "<property name=\"baseline\" value=\"" + junit_text(d.baseline.folder) +
         "\"/><property name=\"candidate\" value=\"" + junit_text(d.candidate.folder) +
         "\"/><property name=\"level\" value=\"" + fixed(d.level, 4) + "\"/></properties>\n";
  // Each configuration's lost episodes (the first 50), with the commands that re-run them.
  constexpr int kListed = 50;
  std::map<std::string, std::pair<int, std::string>> lost;
  for (const ChangedEpisode& e : d.changed) {
    if (e.gained) continue;
    auto& [count, text] = lost[e.configuration];
    if (count++ < kListed)
      text += "  lost " + e.id + ": " + e.candidate.reason +
              "\n    baseline: " + diff_rerun_command(e.baseline, d.baseline.folder, e.id) +
              "\n    candidate: " + diff_rerun_command(e.candidate, d.candidate.folder, e.id) +
              "\n";
    else if (count == kListed + 1)
      text += "  ... more in diff.json\n";
  }
  for (const ConfigurationDiff& c : d.configurations) {
    xml += "    <testcase classname=\"" + junit_text("plantsim diff." + c.world) + "\" name=\"" +
           junit_text(c.planner + " / " + c.controller + " / " + c.fault) + "\">\n";
    const std::string counts = std::to_string(c.pairs) + " episodes: baseline " +
                               std::to_string(c.baseline_succeeded) + " succeeded, candidate " +
                               std::to_string(c.candidate_succeeded) + "; " +
                               std::to_string(c.lost) + " lost, " + std::to_string(c.gained) +
                               " gained, McNemar exact p = " + fixed(c.mcnemar_p, 4);
    if (c.verdict == DiffVerdict::kWorse) {
      std::string text;
      for (const std::string& w : c.why) text += w + "\n";
      text += lost[c.name()].second;
      xml += "      <failure message=\"" + junit_text(c.name() + ": worse; " + counts) +
             "\" type=\"worse_than_baseline\">" + junit_text(text) + "</failure>\n";
    } else {
      xml += "      <system-out>" +
             junit_text(std::string(diff_verdict_name(c.verdict)) + "; " + counts) +
             "</system-out>\n";
    }
    xml += "    </testcase>\n";
  }
  return xml + "  </testsuite>\n</testsuites>\n";
}

}  // namespace plantsim::batch
