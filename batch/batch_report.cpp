// Records into the report's table, chart data and figures.
#include "batch/batch_report.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "batch/batch_gate.h"
#include "batch/batch_summary.h"
#include "batch/record_builds.h"
#include "batch/report_verdicts.h"
#include "batch/summary_tables.h"
#include "batch/wilson_interval.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "render/batch_charts.h"
#include "render/comparison_figure.h"
#include "render/navigation_chart.h"
#include "render/png_io.h"
#include "render/replay_html.h"
#include "render/report.h"
#include "render/run_figure.h"
#include "util/atomic_file.h"
#include "util/c_number.h"
#include "util/csv.h"
#include "util/fixed_text.h"
#include "util/shell_word.h"
#include "worlds/known_keys.h"

namespace plantsim::batch {
namespace {

using nlohmann::json;

using util::fixed;

/// Every failed episode in one table (reason, when, why, the command that re-runs it), and how
/// many of them the gallery below draws.
std::string failure_table_html(const std::vector<std::string>& lines, std::size_t drawn,
                               const std::string& scenario_path) {
  constexpr std::size_t kMaxRows = 2000;
  std::string rows;
  std::size_t failed = 0;
  for (const std::string& line : lines) {
    const json j = json::parse(line);
    if (record_succeeded(j)) continue;
    if (++failed > kMaxRows) continue;
    const auto text = [&](const char* key) {
      const auto it = j.find(key);
      return it != j.end() && it->is_string() ? it->get<std::string>() : std::string("-");
    };
    const auto at = j.find("failure_time_s");
    const std::string id = text("id");
    rows += "<tr><td class=\"l\">" + render::html_escape(id) + "</td><td class=\"l\">" +
            render::html_escape(text("failure")) + "</td><td>" +
            (at != j.end() && at->is_number() ? fixed(at->get<double>(), 1) : "-") +
            "</td><td class=\"l\">" + render::html_escape(text("failure_detail")) +
            "</td><td class=\"l\"><code>" +
            render::html_escape(episode_rerun_command(scenario_path, id)) + "</code></td></tr>\n";
  }
  if (failed == 0) return "<h2>Failures</h2>\n<p>None: every episode succeeded.</p>\n";
  std::string h =
      "<h2>Failures (" + std::to_string(failed) +
      ")</h2>\n<p>Every failed episode with its reason "
      "(docs/failures.md); " +
      std::to_string(drawn) + " of " + std::to_string(failed) +
      " drawn below, one of each reason first" +
      (failed > kMaxRows
           ? "; the first " + std::to_string(kMaxRows) + " listed here, all in episodes.jsonl"
           : "") +
      ".</p>\n<table><tr><th class=\"l\">episode</th><th class=\"l\">reason</th><th>at (s)</th>"
      "<th class=\"l\">detail</th><th class=\"l\">re-run it alone</th></tr>\n";
  return h + rows + "</table>\n";
}

/// What the charts draw, read from the same records the table sums.
struct ChartData {
  std::vector<render::EpisodeOutcome> episodes;
  std::map<std::string, std::vector<render::EpisodePath>> paths;   // by world name
  std::map<double, std::pair<long long, long long>> sweep_counts;  // value -> (succeeded, n)
  std::string sweep_parameter;
  bool pursuit = false;  // the records are of a pursuit: success is a catch
};

render::EpisodeOutcome outcome_of(const json& j) {
  render::EpisodeOutcome e;
  e.method = j["planner"].get<std::string>() + " / " + j["controller"].get<std::string>() + " / " +
             j["fault"].get<std::string>();
  e.world = j.value("world", std::string());
  e.docked = j["docked"].get<bool>();
  e.position_error_m = j.value("position_error_m", 0.0);
  e.heading_error_deg = j.value("heading_error_deg", 0.0);
  const double shortest = j.value("shortest_possible_m", 0.0);
  if (shortest > 0) e.driven_over_shortest = j.value("driven_length_m", 0.0) / shortest;
  e.time_s = j.value("time_s", 0.0);
  if (j.contains("localization_error_max_m") && j["localization_error_max_m"].is_number())
    e.localization_error_max_m = j["localization_error_max_m"].get<double>();
  e.localization_ok = j.value("localization_status", std::string("ok")) == "ok";
  // Navigation metrics: null (not measured) or absent (older records) stay unknown.
  const auto measured = [&](const char* key) {
    const auto it = j.find(key);
    return it != j.end() && it->is_number() ? it->get<double>() : -1.0;
  };
  e.min_clearance_m = measured("min_clearance_m");
  e.rms_jerk_mps3 = measured("rms_jerk_mps3");
  e.controller_ms_median = measured("controller_ms_median");
  return e;
}

ChartData read_chart_data(const std::vector<std::string>& lines) {
  ChartData d;
  for (const std::string& line : lines) {
    const json j = json::parse(line);
    d.episodes.push_back(outcome_of(j));
    render::EpisodePath path;
    path.succeeded = record_succeeded(j);
    d.pursuit = d.pursuit || record_is_pursuit(j);
    if (j.contains("path_mm") && j["path_mm"].is_array())
      for (std::size_t k = 0; k + 1 < j["path_mm"].size(); k += 2)
        path.points.push_back(
            {0.001 * j["path_mm"][k].get<double>(), 0.001 * j["path_mm"][k + 1].get<double>()});
    d.paths[j["world"].get<std::string>()].push_back(std::move(path));
    if (!j.contains("sweep_parameter")) continue;
    d.sweep_parameter = j["sweep_parameter"].get<std::string>();
    char* end = nullptr;
    const std::string value = j["sweep_value"].get<std::string>();
    const double x = util::c_strtod(value.c_str(), &end);
    if (end && *end == '\0' && end != value.c_str()) {
      auto& [k, n] = d.sweep_counts[x];
      k += record_succeeded(j);
      ++n;
    }
  }
  return d;
}

/// Writes one figure into the report's folder and lists it.
class FigureWriter {
 public:
  FigureWriter(render::Report& report, std::string out_dir)
      : report_(report), out_dir_(std::move(out_dir)) {}
  void operator()(const render::Image& img, const std::string& file, const std::string& caption,
                  const std::string& link = "") {
    render::write_png(img, out_dir_ + "/" + file, render::PngSettings::fast());
    report_.figures.push_back({file, caption});
    if (!link.empty()) {
      report_.figure_links.resize(report_.figures.size());
      report_.figure_links.back() = link;
    }
  }

 private:
  render::Report& report_;
  std::string out_dir_;
};

void add_charts(FigureWriter& chart, const ChartData& d,
                const std::vector<ConfigurationVerdict>& verdicts, const std::string& title,
                const Gate& gate) {
  std::vector<render::RateRow> rates;
  for (const ConfigurationVerdict& v : verdicts)
    rates.push_back({v.name(), v.succeeded, v.episodes, v.wilson_low, v.wilson_high,
                     v.threshold.value_or(-1.0)});
  chart(render::draw_success_chart(rates, title), "chart_success.png",
        "Success rate per configuration with its Wilson 95 % interval; the black tick is the gate");
  chart(render::draw_error_strips(d.episodes, {}), "chart_errors.png",
        "Position and heading error of every docked episode against the 2 cm / 2 degree gates");
  chart(render::draw_localization_chart(d.episodes), "chart_localization.png",
        "Each episode's worst localisation error (true against estimated) per method, against 10 "
        "cm, and how many episodes' estimator reported worse than ok");
  chart(render::draw_efficiency_chart(d.episodes), "chart_efficiency.png",
        "Driven length over the shortest possible (ECDF) and time to dock, per method");
  if (std::any_of(d.episodes.begin(), d.episodes.end(),
                  [](const render::EpisodeOutcome& e) { return e.min_clearance_m >= 0; }))
    chart(render::draw_navigation_chart(d.episodes), "chart_navigation.png",
          "Per method: each episode's smallest clearance to the true obstacles on its travel "
          "(red: 0.3 m), its RMS jerk, and the local controller's median compute time per cycle "
          "(wall time)");
  std::set<std::string> worlds;
  for (const render::EpisodeOutcome& e : d.episodes) worlds.insert(e.world);
  if (worlds.size() > 1)
    chart(render::draw_time_by_world(d.episodes), "chart_time_by_world.png",
          "Time to dock world by world (each on its own scale), per method");
  if (d.sweep_counts.empty()) return;
  std::vector<double> values;
  std::vector<render::RateRow> rows;
  for (const auto& [x, kn] : d.sweep_counts) {
    const auto [lo, hi] = wilson_interval(kn.first, kn.second);
    values.push_back(x);
    rows.push_back({fixed(x, 3), kn.first, kn.second, lo, hi, gate.min_success.value_or(-1.0)});
  }
  chart(render::draw_sweep_chart(d.sweep_parameter, values, rows), "chart_sweep.png",
        "Success rate against " + d.sweep_parameter + " with its Wilson 95 % band");
}

void add_world_paths(FigureWriter& chart, const ChartData& d,
                     const std::vector<worlds::World>& worlds) {
  for (const worlds::World& w : worlds) {
    const auto it = d.paths.find(w.name);
    if (it == d.paths.end()) continue;
    chart(render::draw_episode_paths(w, it->second, w.name + ": every episode's driven path",
                                     d.pursuit ? "caught" : "docked"),
          "paths_" + worlds::file_name_component(w.name) + ".png",
          w.name +
              ": every episode's driven path from its own start; failures in vermillion, on top");
  }
}

/// A failed episode's replay on a page of its own beside its figure: the failure first, then the
/// replay that follows the robot to it.
void write_failure_replay(const FailedEpisode& f, const std::string& why, const std::string& path) {
  render::Report page;
  page.title = "FAILED " + f.id;
  page.banner_html = "<div class=\"banner fail\"><b>FAILED</b>: " + render::html_escape(why) +
                     (f.result.failure ? ", at (" + fixed(f.result.failure->pose.x, 2) + ", " +
                                             fixed(f.result.failure->pose.y, 2) + ") m"
                                       : "") +
                     ". <a href=\"../report.html\">Back to the batch report</a></div>";
  page.body_html = render::replay_html(f.plant, f.result);
  render::write_report(page, path);
}

void add_failure_figures(FigureWriter& chart, const std::vector<FailedEpisode>& failures,
                         const std::string& out_dir, const std::string& scenario_path) {
  if (failures.empty()) return;
  std::filesystem::create_directories(out_dir + "/failures");
  for (std::size_t i = 0; i < failures.size(); ++i) {
    const FailedEpisode& f = failures[i];
    render::RunFigureOptions options;
    options.setting = "episode " + f.id;
    options.dock_tolerance_m = f.config.tolerance.lateral_tolerance_m;
    std::string why = episode::status_name(f.result);
    if (f.result.failure)
      why = std::string(robot::to_string(f.result.failure->reason)) + " at " +
            fixed(f.result.failure->time_s, 1) + " s (" + f.result.failure->detail + ")";
    // Numbered: ids cut to a file name's length (or made file-safe) can be alike.
    const std::string stem =
        "failures/" + std::to_string(i + 1) + "_" + worlds::file_name_component(f.id);
    write_failure_replay(f, why, out_dir + "/" + stem + ".html");
    chart(render::draw_run_figure(f.plant, f.result, options), stem + ".png",
          "FAILED " + f.id + ": " + why +
              ". Re-run it alone: " + episode_rerun_command(scenario_path, f.id),
          stem + ".html");
  }
}

/// Each planner's plan on each world from the world file's start, side by side.
void add_plan_comparisons(const std::vector<worlds::World>& worlds,
                          const std::vector<std::string>& planners, const std::string& out_dir,
                          render::Report& report) {
  for (const worlds::World& w : worlds) {
    std::vector<render::ComparisonPanel> panels;
    for (const std::string& name : planners) {
      auto p = planner::make_planner(name, planner::planner_input(w, true));
      const planner::PlanResult r = p->plan(w.start.position(), worlds::staging_pose(w).position());
      render::ComparisonPanel panel{name, {}, {}, false};
      panel.run.planner = name;
      panel.run.status = episode::EpisodeStatus::kPlannerAnswer;
      panel.run.plan_status = r.status;
      panel.run.plan = r.path;
      panel.run.path_length_m = r.length;
      panel.run.plan_stats = r.stats;
      panels.push_back(panel);
    }
    const std::string file = "plans_" + worlds::file_name_component(w.name) + ".png";
    // One panel needs no 1800-pixel canvas.
    const int width = panels.size() == 1 ? 1000 : panels.size() == 2 ? 1500 : 1800;
    render::write_png(
        render::draw_comparison(
            w, panels, w.name + ": plans from the world file's start (not an episode's)", width),
        out_dir + "/" + file, render::PngSettings::fast());
    report.figures.push_back(
        {file, w.name + ": each planner's plan from the world file's start to the staging pose "
                        "(episodes start from random poses)"});
  }
}

}  // namespace

void write_batch_report(const std::vector<std::string>& lines, const std::string& out_dir,
                        const std::string& title, const std::string& command,
                        const std::vector<worlds::World>* worlds_for_figures,
                        const std::vector<std::string>& planners, const Gate& gate, bool charts,
                        const util::MadeBy& made_by, const std::vector<FailedEpisode>& failures,
                        const std::string& scenario_path, bool accept_mixed_builds) {
  const std::string csv = summary_csv(lines, &gate);
  util::write_file_atomically(out_dir + "/summary.csv", csv);
  const std::string sweep = sweep_csv(lines);
  if (!sweep.empty()) util::write_file_atomically(out_dir + "/sweep.csv", sweep);
  const std::vector<ConfigurationVerdict> verdicts = judge_configurations(lines, gate);
  nlohmann::json summary = batch_summary_json(lines, verdicts, gate, title, command);
  summary["made_by"] = nlohmann::json::parse(made_by.json().dump());
  const std::vector<BuildCount> builds = record_builds(lines);
  const bool mixed = builds.size() > 1;
  summary["builds"] = builds_json(builds);
  if (mixed)
    summary["mixed_builds"] = {{"builds", builds.size()}, {"accepted", accept_mixed_builds}};
  util::write_file_atomically(out_dir + "/summary.json", summary.dump(1) + "\n");
  render::Report report;
  report.title = title;
  report.command = command;
  report.made_by = made_by.text() + (mixed ? " From " + builds_text(builds) + "." : "");
  report.banner_html = mixed_builds_banner_html(builds, accept_mixed_builds) +
                       verdict_banner_html(verdicts, gate, mixed && !accept_mixed_builds);
  const std::string details = fill_verdict_table(report, csv, verdicts, gate.statistic);
  report.notes =
      "Success rate with its 95 % Wilson interval; plan / optimum compares the planned length with "
      "the exact visibility-graph optimum from the same start; errors are over docked episodes; "
      "summary.csv has every column.";
  report.files = {"episodes.jsonl", "summary.csv", "summary.json"};
  if (!sweep.empty()) report.files.push_back("sweep.csv");
  report.body_html = details + failure_table_html(lines, failures.size(), scenario_path);
  if (charts) {
    const ChartData data = read_chart_data(lines);
    FigureWriter chart(report, out_dir);
    add_charts(chart, data, verdicts, title, gate);
    if (worlds_for_figures) add_world_paths(chart, data, *worlds_for_figures);
    add_failure_figures(chart, failures, out_dir, scenario_path);
    if (worlds_for_figures) add_plan_comparisons(*worlds_for_figures, planners, out_dir, report);
  }
  render::write_report(report, out_dir + "/report.html");
}

}  // namespace plantsim::batch
