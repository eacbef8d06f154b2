// The verdict first (see the header).
#include "batch/report_verdicts.h"

#include <algorithm>
#include <cstdlib>

#include "util/csv.h"
#include "util/fixed_text.h"

namespace plantsim::batch {
namespace {

using util::fixed;

std::string interval(const ConfigurationVerdict& v) {
  return fixed(v.success_rate, 3) + " (95 % " + fixed(v.wilson_low, 3) + " to " +
         fixed(v.wilson_high, 3) + ")";
}

/// "PASS: 0.990 >= 0.950, its 95 % low 0.948 below it (the sample cannot tell)".
std::string verdict_text(const ConfigurationVerdict& v, GateStatistic statistic) {
  const double value = statistic == GateStatistic::kWilsonLow ? v.wilson_low : v.success_rate;
  const std::string pooled = v.world == kAllWorlds ? "all worlds pooled: " : "";
  std::string text = pooled + (v.passed ? "PASS " : "FAIL ") + statistic_name(statistic) + " " +
                     fixed(value, 3) + (v.passed ? " >= " : " < ") + fixed(*v.threshold, 3);
  if (!v.passed) return text + ", short by " + fixed(*v.threshold - value, 3);
  if (statistic == GateStatistic::kSuccessRate)
    text += v.lower_bound_clears() ? "; its 95 % low " + fixed(v.wilson_low, 3) + " clears it too"
                                   : "; its 95 % low " + fixed(v.wilson_low, 3) +
                                         " is below it (the sample cannot tell)";
  return text;
}

/// The verdict that judges a summary row: its own, or its configuration's over all worlds.
const ConfigurationVerdict* verdict_of(const std::vector<std::string>& cells,
                                       const std::vector<ConfigurationVerdict>& verdicts) {
  if (cells.size() < 4) return nullptr;
  for (const ConfigurationVerdict& c : verdicts)
    if ((c.world == cells[0] || c.world == kAllWorlds) && c.planner == cells[1] &&
        c.controller == cells[2] && c.fault == cells[3])
      return &c;
  return nullptr;
}

struct Column {
  const char* key;
  const char* title;
};

const std::vector<Column> kMain = {{"world", "world"},
                                   {"planner", "planner"},
                                   {"controller", "controller"},
                                   {"fault", "fault"},
                                   {"episodes", "episodes"},
                                   {"succeeded", "succeeded"},
                                   {"mean_position_error_mm", "position error (mm)"},
                                   {"mean_time_s", "time (s)"},
                                   {"collisions", "collisions"},
                                   {"docked_lost", "docked but lost"}};
const std::vector<Column> kDetail = {
    {"world", "world"},
    {"planner", "planner"},
    {"controller", "controller"},
    {"fault", "fault"},
    {"mean_heading_error_deg", "heading error (deg)"},
    {"mean_stops", "stops"},
    {"mean_replans", "replans"},
    {"path_over_optimum", "plan / optimum"},
    {"max_localization_error_mm", "worst localisation error (mm)"},
    {"p95_localization_error_mm", "95th pct localisation error (mm)"},
    {"localization_not_ok", "localisation not ok at the end"},
    {"docked_not_ok", "docked, estimate not ok"},
    {"localization_not_ok_share", "share of time not ok"}};

// The navigation-benchmark metrics per configuration (batch/navigation_tally.h; the controller's
// times are wall times of this machine, docs/batch.md).
const std::vector<Column> kNavigation = {
    {"world", "world"},
    {"planner", "planner"},
    {"controller", "controller"},
    {"fault", "fault"},
    {"min_clearance_m", "min clearance (m)"},
    {"mean_clearance_m", "mean clearance (m)"},
    {"near_obstacle_share", "share of time within 0.3 m"},
    {"mean_rms_jerk_mps3", "RMS jerk (m/s^3)"},
    {"mean_rms_angular_accel_radps2", "RMS angular accel. (rad/s^2)"},
    {"controller_ms_median", "controller median (ms)"},
    {"controller_ms_p99_max", "controller p99, worst (ms)"}};

std::vector<int> indices(const std::vector<std::string>& header, const std::vector<Column>& cols,
                         std::vector<std::string>* titles) {
  std::vector<int> out;
  for (const Column& c : cols) {
    const auto it = std::find(header.begin(), header.end(), c.key);
    if (it == header.end()) continue;
    out.push_back(static_cast<int>(it - header.begin()));
    if (titles) titles->push_back(c.title);
  }
  return out;
}

std::string cell(const std::vector<std::string>& cells, int i) {
  return static_cast<std::size_t>(i) < cells.size() ? cells[static_cast<std::size_t>(i)] : "";
}

/// Means over docked episodes are no value when none docked: "-", not a perfect 0.000.
std::string measured_cell(const std::vector<std::string>& header,
                          const std::vector<std::string>& cells, int i) {
  const std::string& key = header[static_cast<std::size_t>(i)];
  const auto succeeded = std::find(header.begin(), header.end(), "succeeded") - header.begin();
  const bool over_docked = key == "mean_position_error_mm" || key == "mean_heading_error_deg";
  if (over_docked && cell(cells, static_cast<int>(succeeded)) == "0") return "-";
  return cell(cells, i).empty() ? "-" : cell(cells, i);  // no value, never a perfect 0
}

/// The failed_<reason> columns that are not zero, as "reason count, ...".
std::string failures_of(const std::vector<std::string>& header,
                        const std::vector<std::string>& cells) {
  std::string failures;
  for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i) {
    if (header[i].rfind("failed_", 0) != 0 || cells[i] == "0") continue;
    failures += (failures.empty() ? "" : ", ") + header[i].substr(7) + " " + cells[i];
  }
  return failures.empty() ? "-" : failures;
}

/// Below this many episodes the nearest-rank 95th percentile is the worst value itself
/// (rank ceil(0.95 n) = n for n < 20): a column of it repeats the worst's.
constexpr long kPercentileEpisodes = 20;

bool small_sample(const std::vector<std::string>& header, const std::vector<std::string>& cells) {
  const auto episodes = std::find(header.begin(), header.end(), "episodes") - header.begin();
  const std::string n = cell(cells, static_cast<int>(episodes));
  return n.empty() || std::strtol(n.c_str(), nullptr, 10) < kPercentileEpisodes;
}

/// A table of `cols` of every summary row, under `heading`. The 95th percentile's column goes
/// when every row is a small sample; a small sample's cell in it says it equals the worst.
std::string column_table(const std::string& heading, const std::vector<std::string>& header,
                         const std::vector<std::vector<std::string>>& rows,
                         const std::vector<Column>& cols) {
  bool all_small = true;
  for (std::size_t r = 1; r < rows.size(); ++r)
    all_small = all_small && small_sample(header, rows[r]);
  std::vector<Column> shown;
  for (const Column& c : cols)
    if (!(all_small && std::string(c.key) == "p95_localization_error_mm")) shown.push_back(c);
  std::vector<std::string> titles;
  const std::vector<int> picked = indices(header, shown, &titles);
  std::string h = "<h2>" + render::html_escape(heading) + "</h2>\n<table><tr>";
  for (const std::string& t : titles) h += "<th>" + render::html_escape(t) + "</th>";
  h += "</tr>\n";
  for (std::size_t r = 1; r < rows.size(); ++r) {
    h += "<tr>";
    for (int i : picked) {
      const bool percentile = header[static_cast<std::size_t>(i)] == "p95_localization_error_mm";
      h += "<td>" +
           render::html_escape(percentile && small_sample(header, rows[r])
                                   ? "= worst (under 20 episodes)"
                                   : measured_cell(header, rows[r], i)) +
           "</td>";
    }
    h += "</tr>\n";
  }
  return h + "</table>\n";
}

}  // namespace

std::string mixed_builds_banner_html(const std::vector<BuildCount>& builds, bool accepted) {
  if (builds.size() < 2) return "";
  return std::string("<div class=\"banner ") + (accepted ? "none" : "mixed") +
         "\"><b>MIXED BUILDS</b>: " + render::html_escape(builds_text(builds)) +
         (accepted ? " (accepted with --accept-mixed-builds)."
                   : ". The verdict below is not one build's: re-run with --fresh, or accept the "
                     "mix with --accept-mixed-builds.") +
         "</div>\n";
}

std::string verdict_banner_html(const std::vector<ConfigurationVerdict>& verdicts, const Gate& gate,
                                bool unaccepted_mix) {
  int gated = 0;
  std::vector<const ConfigurationVerdict*> failing, unsure;
  for (const ConfigurationVerdict& v : verdicts) {
    if (!v.threshold) continue;
    ++gated;
    if (!v.passed)
      failing.push_back(&v);
    else if (!v.lower_bound_clears() && gate.statistic == GateStatistic::kSuccessRate)
      unsure.push_back(&v);
  }
  const std::string requirement =
      std::string("the gate: ") + statistic_name(gate.statistic) + " at or above " +
      (gate.min_success ? fixed(*gate.min_success, 3) : std::string("each rule's threshold")) +
      (gate.rules.empty()
           ? ""
           : " (" + std::to_string(gate.rules.size()) + " rules for some configurations)") +
      (gate.pool_worlds ? ", each configuration pooled over all worlds" : "");
  std::string h;
  if (gated == 0)
    return "<div class=\"banner none\"><b>NO GATE</b>: the scenario sets no min_success; the "
           "table below judges nothing.</div>\n";
  if (failing.empty()) {
    // A pass over a mix of builds is no build's pass: not green until the mix is accepted.
    h = std::string("<div class=\"banner ") + (unaccepted_mix ? "mixed" : "pass") +
        "\"><b>PASS</b>" + (unaccepted_mix ? " (mixed builds)" : "") + ": all " +
        std::to_string(gated) + " gated configurations meet " + render::html_escape(requirement) +
        ".";
    if (!unsure.empty())
      h += " " + std::to_string(unsure.size()) +
           " of them pass by their success rate while their 95 % lower bound is below the "
           "threshold: more episodes would tell.";
    return h + "</div>\n";
  }
  h = "<div class=\"banner fail\"><b>FAIL</b>: " + std::to_string(failing.size()) + " of " +
      std::to_string(gated) + " gated configurations are below " +
      render::html_escape(requirement) + ":<ul>";
  for (const ConfigurationVerdict* v : failing)
    h += "<li>" + render::html_escape(v->name()) + ": " + std::to_string(v->succeeded) + "/" +
         std::to_string(v->episodes) + " " + v->outcome() + ", success " + interval(*v) + "; " +
         render::html_escape(verdict_text(*v, gate.statistic)) + "</li>";
  return h + "</ul></div>\n";
}

std::string fill_verdict_table(render::Report& report, const std::string& csv,
                               const std::vector<ConfigurationVerdict>& verdicts,
                               GateStatistic statistic) {
  std::vector<std::vector<std::string>> rows;
  for (std::size_t start = 0; start < csv.size();) {
    const std::size_t end = std::min(csv.find('\n', start), csv.size());
    rows.push_back(util::csv_split(csv.substr(start, end - start)));
    start = end + 1;
  }
  if (rows.empty()) return "";
  const std::vector<std::string> header = rows.front();
  std::vector<std::string> main_titles;
  const std::vector<int> main = indices(header, kMain, &main_titles);
  const auto rate = std::find(header.begin(), header.end(), "success_rate") - header.begin();
  const auto low = std::find(header.begin(), header.end(), "ci95_low") - header.begin();
  const auto high = std::find(header.begin(), header.end(), "ci95_high") - header.begin();
  report.headers = {main_titles.begin(),
                    main_titles.begin() + std::min<std::size_t>(4, main_titles.size())};
  report.headers.push_back("gate");
  report.headers.insert(report.headers.end(),
                        main_titles.begin() + std::min<std::size_t>(4, main_titles.size()),
                        main_titles.end());
  report.headers.push_back("success (95 % interval)");
  report.headers.push_back("failures by reason");
  struct Row {
    bool failed;
    std::vector<std::string> cells;
  };
  std::vector<Row> table;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const std::vector<std::string>& cells = rows[r];
    const ConfigurationVerdict* v = verdict_of(cells, verdicts);
    Row row{v && v->threshold && !v->passed, {}};
    const std::size_t names = std::min<std::size_t>(4, main.size());  // world .. fault
    for (std::size_t k = 0; k < names; ++k) row.cells.push_back(cell(cells, main[k]));
    row.cells.push_back(v && v->threshold ? verdict_text(*v, statistic) : "not gated");
    for (std::size_t k = names; k < main.size(); ++k)
      row.cells.push_back(measured_cell(header, cells, main[k]));
    row.cells.push_back(cell(cells, static_cast<int>(rate)) + " (" +
                        cell(cells, static_cast<int>(low)) + " to " +
                        cell(cells, static_cast<int>(high)) + ")");
    row.cells.push_back(failures_of(header, cells));
    table.push_back(std::move(row));
  }
  std::stable_sort(table.begin(), table.end(),
                   [](const Row& a, const Row& b) { return a.failed && !b.failed; });
  for (Row& row : table) {
    report.rows.push_back(std::move(row.cells));
    report.row_classes.push_back(row.failed ? "fail" : "");
  }
  return column_table("Details per configuration", header, rows, kDetail) +
         column_table("Navigation per configuration (docs/batch.md: navigation metrics)", header,
                      rows, kNavigation);
}

}  // namespace plantsim::batch
