// `plantsim summarize DIR...`: gathers the summary.json of several runs into one Markdown
// table, and with --html into a dashboard (render/dashboard.h) that also lists the comparisons,
// batches and coverage reports given with --link.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string_view>
#include <tuple>
#include <vector>

#include "app/commands.h"
#include "app/dashboard_history.h"
#include "app/output_kinds.h"
#include "render/dashboard.h"
#include "render/overall_verdict.h"
#include "render/report.h"
#include "util/atomic_file.h"
#include "util/build_stamp.h"
#include "util/fixed_text.h"
#include "util/input_file.h"
#include "util/made_by.h"
#include "util/unicode_text.h"
#include "worlds/json_input.h"
#include "worlds/world_error.h"

namespace plantsim::app {
namespace {

using util::fixed;

/// What a run's command changed from the defaults: "config noisy_sensing.json, seed 3".
std::string setting_of(const std::string& command) {
  std::string out;
  for (const char* option :
       {"--config", "--seed", "--travel", "--start", "--charger", "--undock"}) {
    const std::size_t at = command.find(std::string(option));
    if (at == std::string::npos) continue;
    std::size_t begin = at + std::strlen(option);
    while (begin < command.size() &&
           (command[begin] == ' ' || command[begin] == '=' || command[begin] == '\''))
      ++begin;
    std::size_t end = command.find_first_of(" '", begin);
    std::string value =
        command.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    if (std::string(option) == "--undock") value.clear();
    if (std::string(option) == "--config") value = std::filesystem::path(value).filename().string();
    out += (out.empty() ? "" : ", ") + std::string(option + 2) + (value.empty() ? "" : " " + value);
  }
  return out.empty() ? "defaults" : out;
}

/// The batch line's counts (throws nlohmann::json::exception on a field of another type).
/// Records of more than one build (summary.json's "mixed_builds") not accepted, by the batch or
/// by `accept_mixed`, give the verdict "mixed": no pass (docs/batch.md).
std::string batch_counts(const nlohmann::json& j, std::string& verdict, bool accept_mixed) {
  verdict = j.value("verdict", "");
  std::string line = std::to_string(j.value("succeeded", 0LL)) + " of " +
                     std::to_string(j.value("episodes", 0LL)) + " episodes succeeded";
  std::string reasons;
  const nlohmann::json by_reason = j.value(
      "failures_by_reason", nlohmann::json::object());  // a local: items() does not keep it alive
  for (const auto& [reason, count] : by_reason.items())
    reasons +=
        (reasons.empty() ? "" : ", ") + reason + " " + std::to_string(count.get<long long>());
  if (!reasons.empty()) line += "; failures: " + reasons;
  if (j.value("succeeded_lost", 0LL) > 0)  // integrity: a success is not a clean one when lost
    line +=
        "; " + std::to_string(j.value("succeeded_lost", 0LL)) + " succeeded with the estimate lost";
  const nlohmann::json mixed = j.value("mixed_builds", nlohmann::json::object());
  if (!mixed.empty()) {
    const bool accepted = accept_mixed || mixed.value("accepted", false);
    line += "; records of " + std::to_string(mixed.value("builds", 0LL)) + " builds" +
            (accepted ? " (accepted)" : ", not accepted (--accept-mixed-builds)");
    if (!accepted && verdict != "failed") verdict = "mixed";
  }
  const nlohmann::json gate = j.value("gate", nlohmann::json::object());
  const long long gated = gate.value("gated_configurations", 0LL);
  if (gated > 0)
    line += "; " + std::to_string(gate.value("below_threshold", 0LL)) + " of " +
            std::to_string(gated) + " gated configurations below their threshold by " +
            gate.value("statistic", std::string("?")) + ", " +
            std::to_string(gate.value("lower_bound_below_threshold", 0LL)) +
            " with the 95 % lower bound below it";
  return line;
}

/// A batch folder in one line from its summary.json: episodes, failures by reason, the gate.
std::string batch_line(const std::string& dir, std::string& verdict, bool accept_mixed) {
  nlohmann::json j;
  try {
    const std::string path = dir + "/summary.json";
    j = worlds::parse_json_input(util::read_input_file(path, 64u << 20), path);
  } catch (const std::exception&) {
    return "no summary.json (written by plantsim batch and merge since issue 37): see its report";
  }
  try {
    return batch_counts(j, verdict, accept_mixed);
  } catch (const nlohmann::json::exception&) {  // a field of another type: not plantsim's file
    verdict.clear();
    return "a summary.json plantsim did not write (a field of the wrong type): see its report";
  }
}

/// Why a folder's outputs may not be this build's, from its summary.json's "made_by": empty
/// when this build made them.
std::string stale_note(const std::string& summary_path) {
  nlohmann::json j;
  try {
    j = worlds::parse_json_input(util::read_input_file(summary_path, 64u << 20), summary_path);
  } catch (const std::exception&) {
    return "";  // no summary.json: said elsewhere
  }
  const auto m = j.find("made_by");
  if (m == j.end() || !m->is_object() || !m->contains("commit"))
    return "no build stamp: made before plantsim stamped its outputs";
  const util::BuildStamp& b = util::build_stamp();
  const std::string commit = (*m)["commit"].is_string() ? (*m)["commit"].get<std::string>() : "?";
  const std::string date = m->value("date", std::string("?"));
  if (commit != b.commit) return "made by another build (commit " + commit + ", " + date + ")";
  if (m->value("dirty", false) || b.dirty)
    return "made by commit " + commit + " with uncommitted changes (" + date +
           "): which changes, nobody can tell";
  return "";
}

/// A tuning folder in one line: its verdict on the validation episodes (summary.json).
std::string tune_line(const std::string& dir) {
  try {
    const std::string path = dir + "/summary.json";
    const nlohmann::json j = worlds::parse_json_input(util::read_input_file(path, 64u << 20), path);
    return j.at("verdict").get<std::string>();
  } catch (const std::exception&) {
    return "no readable summary.json: the tuning did not finish; see its evaluations.jsonl";
  }
}

/// A linked report, its kind told by what its folder holds, with the figure that shows it best.
render::DashboardLink link_to(const std::string& report, const std::string& base,
                              bool accept_mixed) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(report).parent_path();
  render::DashboardLink l;
  l.report = fs::relative(report, base).string();
  l.title = dir.filename().string();
  auto rel = [&](const std::string& f) { return fs::relative(dir / f, base).string(); };
  if (!fs::exists(report)) {  // named, so that a missing report shows instead of vanishing
    l.kind = "report";
    l.line = "missing: the command that writes it failed or has not run";
  } else if (fs::path(report).extension() == ".png") {  // a chart on its own
    l.kind = "chart";
    l.title = fs::path(report).stem().string();
    l.thumbnail = l.report;
    l.line = dir.filename().string() + "/" + fs::path(report).filename().string();
  } else if (fs::exists(dir / "summary.csv")) {
    l.kind = "batch";
    if (fs::exists(dir / "chart_success.png")) l.thumbnail = rel("chart_success.png");
    l.line = batch_line(dir.string(), l.verdict, accept_mixed);
    l.stale = stale_note((dir / "summary.json").string());
  } else if (fs::exists(dir / "evaluations.jsonl") && fs::exists(dir / "best.json")) {
    l.kind = "tune";
    if (fs::exists(dir / "convergence.png")) l.thumbnail = rel("convergence.png");
    l.line = tune_line(dir.string());
    l.stale = stale_note((dir / "summary.json").string());
  } else if (fs::exists(dir / "coverage.png")) {
    l.kind = "coverage";
    l.thumbnail = rel("coverage.png");
  } else if (fs::exists(dir / "comparison.png")) {
    l.kind = "comparison";
    l.thumbnail = rel("comparison.png");
  } else {
    l.kind = "report";
  }
  return l;
}

/// A run's summary.json with every field the table reads of its type (a hand-edited or foreign
/// file is refused naming the field, never half-read).
nlohmann::json read_summary(const std::string& dir) {
  const std::string path = dir + "/summary.json";
  nlohmann::json j;
  try {
    j = worlds::parse_json_input(util::read_input_file(path, 64u << 20), path);
  } catch (const util::InputFileError& e) {
    throw std::invalid_argument(path + ": " + e.what());
  }
  if (!j.is_object()) throw worlds::WorldError(path, "", "expected a JSON object");
  using Check = bool (nlohmann::json::*)() const noexcept;
  const std::vector<std::tuple<const char*, Check, const char*>> fields = {
      {"world", &nlohmann::json::is_string, "text"},
      {"planner", &nlohmann::json::is_string, "text"},
      {"travel", &nlohmann::json::is_string, "text"},
      {"status", &nlohmann::json::is_string, "text"},
      {"command", &nlohmann::json::is_string, "text"},
      {"error_measured", &nlohmann::json::is_boolean, "true or false"},
      {"docked", &nlohmann::json::is_boolean, "true or false"},
      {"caught", &nlohmann::json::is_boolean, "true or false"},
      {"position_error_m", &nlohmann::json::is_number, "a number"},
      {"heading_error_deg", &nlohmann::json::is_number, "a number"},
      {"time_s", &nlohmann::json::is_number, "a number"},
      {"path_length_m", &nlohmann::json::is_number, "a number"},
      {"driven_length_m", &nlohmann::json::is_number, "a number"},
      {"collisions", &nlohmann::json::is_number_unsigned, "a whole number from 0"},
      {"retries", &nlohmann::json::is_number_unsigned, "a whole number from 0"},
      {"stops", &nlohmann::json::is_number_unsigned, "a whole number from 0"},
      {"replans", &nlohmann::json::is_number_unsigned, "a whole number from 0"}};
  for (const auto& [key, is_kind, kind] : fields) {
    const auto it = j.find(key);
    if (it != j.end() && !((*it).*is_kind)())
      throw worlds::WorldError(path, key, std::string("expected ") + kind);
  }
  return j;
}

/// Text from a run's files as one Markdown table cell: shown as written, never read as Markdown
/// or HTML ('|' split columns, a name in [..](..) made a link), controls escaped.
std::string markdown_cell(const std::string& text) {
  std::string out;
  for (const char c : util::printable(text)) {
    if (std::string_view("\\`*_{}[]()<>#+-!|~&:").find(c) != std::string_view::npos) out += '\\';
    out += c;
  }
  return out;
}

/// The run's row of the Markdown table (the dashboard's columns), its figure linked from `link`.
std::string markdown_row(const nlohmann::json& j, const std::string& link) {
  // An episode that did not dock has no docking error (it was the distance to the charger).
  const bool measured =
      j.value("error_measured", true) && (j.value("docked", false) || j.value("caught", false));
  std::string row = "| " + markdown_cell(j.value("world", "?")) + " | " +
                    markdown_cell(j.value("planner", "?")) + " | " +
                    markdown_cell(j.value("travel", "path")) + " | " +
                    markdown_cell(j.value("status", "?"));
  for (const std::string& cell :
       {measured ? fixed(1000.0 * j.value("position_error_m", 0.0), 1) : std::string("n/a"),
        measured ? fixed(j.value("heading_error_deg", 0.0), 2) : std::string("n/a"),
        std::to_string(j.value("collisions", 0)), std::to_string(j.value("retries", 0)),
        std::to_string(j.value("stops", 0)), std::to_string(j.value("replans", 0)),
        fixed(j.value("time_s", 0.0), 1), fixed(j.value("path_length_m", 0.0), 2),
        fixed(j.value("driven_length_m", 0.0), 2)})
    row += " | " + cell;
  // The link percent-encoded: a folder named "javascript:..." is a path, never a scheme.
  return row + " | [run.png](" + render::url_attribute(link + "/run.png") + ") |\n";
}

/// The run's card on the dashboard (its cells in the order of kDashboardHeaders).
render::DashboardRun dashboard_run(const nlohmann::json& j, const std::string& dir,
                                   const std::string& html_base) {
  const bool measured =
      j.value("error_measured", true) && (j.value("docked", false) || j.value("caught", false));
  render::DashboardRun run;
  run.folder = std::filesystem::relative(dir, html_base.empty() ? "." : html_base).string();
  run.world = j.value("world", "?");
  run.setting = setting_of(j.value("command", ""));
  run.status = j.value("status", "?");
  // A failure says why and when, where the table has room (summary.json: failure, failure_time_s).
  if (j.contains("failure") && j["failure"].is_string() &&
      j["failure"].get<std::string>() != run.status) {
    run.status += ": " + j["failure"].get<std::string>();
    if (j.contains("failure_time_s") && j["failure_time_s"].is_number())
      run.status += " at " + fixed(j["failure_time_s"].get<double>(), 1) + " s";
  }
  run.succeeded = j.value("docked", false) || j.value("caught", false);
  run.cells = {j.value("planner", "?") +
                   (j.value("travel", "path") == "path" ? "" : " (" + j.value("travel", "") + ")"),
               measured ? fixed(1000.0 * j.value("position_error_m", 0.0), 1) : "n/a",
               measured ? fixed(j.value("heading_error_deg", 0.0), 2) : "n/a",
               std::to_string(j.value("collisions", 0)),
               std::to_string(j.value("retries", 0)),
               std::to_string(j.value("stops", 0)),
               std::to_string(j.value("replans", 0)),
               fixed(j.value("time_s", 0.0), 1),
               fixed(j.value("path_length_m", 0.0), 2),
               fixed(j.value("driven_length_m", 0.0), 2)};
  for (const char* f : {"run.png", "timeplots.png"})
    if (std::filesystem::exists(dir + "/" + f)) run.figures.push_back(f);
  run.stale = stale_note(dir + "/summary.json");
  return run;
}

const std::vector<std::string> kDashboardHeaders = {"planner",
                                                    "position error (mm)",
                                                    "heading error (deg)",
                                                    "collisions",
                                                    "retries",
                                                    "stops",
                                                    "replans",
                                                    "time (s)",
                                                    "planned (m)",
                                                    "driven (m)"};

struct SummarizeOptions {
  std::vector<std::string> dirs;
  std::string out;
  std::string html;
  std::vector<std::string> links;
  bool accept_mixed_builds = false;  ///< batches of records of several builds judged all the same
};

/// A folder given as a run that is a batch's or a tuning's: taken as a link to its report.
bool report_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  return fs::exists(fs::path(dir) / "summary.csv") ||
         fs::exists(fs::path(dir) / "evaluations.jsonl");
}

/// The dashboard's sections below the runs, in Markdown: each linked report with its verdict and
/// its line (a batch's counts and failures by reason, a tuning's verdict).
std::string markdown_links(const std::vector<render::DashboardLink>& links) {
  std::string md;
  for (const auto& [kind, heading] :
       std::vector<std::pair<std::string, std::string>>{{"batch", "Batches"},
                                                        {"tune", "Tunings"},
                                                        {"comparison", "Comparisons"},
                                                        {"coverage", "Coverage"},
                                                        {"chart", "Charts"},
                                                        {"report", "Other reports"}}) {
    std::string items;
    for (const render::DashboardLink& l : links) {
      if (l.kind != kind) continue;
      const std::string verdict = l.verdict == "passed"   ? "**PASS** "
                                  : l.verdict == "failed" ? "**FAIL** "
                                                          : "";
      items += "- " + verdict + "[" + markdown_cell(l.title) + "](" +
               render::url_attribute(l.report) + ")" +
               (l.line.empty() ? "" : ": " + markdown_cell(l.line)) +
               (l.stale.empty() ? "" : " (" + markdown_cell(l.stale) + ")") + "\n";
    }
    if (!items.empty()) md += "\n## " + heading + "\n\n" + items;
  }
  return md;
}

int summarize(const SummarizeOptions& opt) {
  // Before any work: an output that cannot be written is bad input (exit 2), not a failure.
  if (!opt.out.empty()) util::check_output_file(opt.out, "--out", summary_markdown_kind());
  if (!opt.html.empty()) util::check_output_file(opt.html, "--html", dashboard_kind());
  const util::MadeBy made_by;
  std::string md =
      made_by.text() +
      "\n\n| world | planner | travel | status | position error (mm) | "
      "heading error (deg) | collisions | retries | stops | replans | time (s) | planned (m) | "
      "driven (m) | figure |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::vector<render::DashboardRun> runs;
  const std::string html_base =
      opt.html.empty() ? "." : std::filesystem::path(opt.html).parent_path().string();
  // Links relative to where the table is written, so they work when it is opened.
  const std::string base =
      opt.out.empty() ? "." : std::filesystem::path(opt.out).parent_path().string();
  std::vector<std::filesystem::path> seen;
  std::vector<std::string> link_reports = opt.links;
  for (const auto& d : opt.dirs) {
    if (report_folder(d)) {  // a batch or a tuning: its report, as --link would name it
      link_reports.push_back((std::filesystem::path(d) / "report.html").string());
      continue;
    }
    // A folder named twice (by two globs, or with and without a trailing slash) is one run.
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(d);
    if (std::find(seen.begin(), seen.end(), canonical) != seen.end()) continue;
    seen.push_back(canonical);
    const nlohmann::json j = read_summary(d);
    md += markdown_row(j, std::filesystem::relative(d, base.empty() ? "." : base).string());
    runs.push_back(dashboard_run(j, d, html_base));
  }
  if (runs.empty()) md += "| (no runs) |\n";
  // The links, made relative to the dashboard and (for summary.md) to the table.
  std::vector<render::DashboardLink> links, md_links;
  std::vector<std::string> summaries;
  for (const auto& l : link_reports) {
    links.push_back(link_to(l, html_base.empty() ? "." : html_base, opt.accept_mixed_builds));
    md_links.push_back(link_to(l, base.empty() ? "." : base, opt.accept_mixed_builds));
    summaries.push_back((std::filesystem::path(l).parent_path() / "summary.json").string());
  }
  md += markdown_links(md_links);
  if (!opt.html.empty()) {
    // Each batch's runs over time, beside the dashboard (history.jsonl).
    update_history(
        (std::filesystem::path(html_base.empty() ? "." : html_base) / "history.jsonl").string(),
        links, summaries);
    util::write_file_atomically(
        opt.html,
        render::dashboard_html("plantsim results", kDashboardHeaders, runs, links, made_by.text()));
  }
  // One verdict over the runs and the linked reports, first in summary.md as on the dashboard.
  const render::OverallVerdict verdict = render::overall_verdict(runs, links);
  md = "# plantsim results: " + verdict.word + "\n\n**" + verdict.word +
       "**: " + markdown_cell(verdict.why) + "\n\n" + md;
  if (opt.out.empty())
    std::cout << md;
  else
    util::write_file_atomically(opt.out, md);
  return verdict.failed() ? kExitFailed : kExitOk;
}

}  // namespace

std::function<int()> add_summarize_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("summarize", "Gather run folders' summary.json into a Markdown table");
  auto opt = std::make_shared<SummarizeOptions>();
  cmd->add_option("dirs", opt->dirs,
                  "Run output folders; a batch's or a tuning's folder is listed as its report")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--out", opt->out, "Write here instead of stdout");
  cmd->add_option("--html", opt->html,
                  "Also write an HTML dashboard: every run's thumbnail, status and figures, and "
                  "the linked reports");
  cmd->add_option("--link", opt->links,
                  "Further reports (or PNG charts) to link from the dashboard");
  cmd->add_flag("--accept-mixed-builds", opt->accept_mixed_builds,
                "Judge batches whose records several builds ran (else the verdict is not PASS)");
  return [opt]() { return summarize(*opt); };
}

}  // namespace plantsim::app
