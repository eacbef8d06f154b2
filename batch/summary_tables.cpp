// The CSV tables of a batch (see the header).
#include "batch/summary_tables.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "batch/batch_gate.h"
#include "batch/navigation_tally.h"
#include "batch/wilson_interval.h"
#include "robot/failure.h"
#include "util/c_number.h"
#include "util/csv.h"

namespace plantsim::batch {

using nlohmann::json;

namespace {

/// One configuration's episodes summed (summary.csv's row).
struct ConfigurationTally {
  std::int64_t n = 0, succeeded = 0, docked = 0, collisions = 0, retries = 0, trapped = 0,
               timeouts = 0;
  std::int64_t robot_collisions = 0, localization_not_ok = 0, charging = 0;
  std::int64_t docked_not_ok = 0, docked_lost = 0;  ///< docked with the estimate not ok, or lost
  std::vector<double> localization_errors;  ///< each episode's worst, for the 95th percentile
  double not_ok_s = 0;                      ///< time the estimator reported anything but ok
  double stops = 0, replans = 0, recoveries = 0;
  double localization_error_max = 0;
  double time = 0, ratio = 0, pos = 0, heading = 0, driven_ratio = 0, local_minima = 0,
         wall_follows = 0;
  std::int64_t ratio_n = 0, driven_n = 0;
  std::array<std::int64_t, robot::kAllFailureReasons.size()>
      failed{};  // per reason, in kAllFailureReasons' order
  NavigationTally navigation;
  void add(const json& j);
  /// The row's numbers after its four names, comma first, newline last.
  std::string row() const;
};

void ConfigurationTally::add(const json& j) {
  ConfigurationTally& a = *this;
  ++a.n;
  const bool docked = j["docked"].get<bool>();
  a.succeeded += record_succeeded(j);
  a.docked += docked;  // docking errors are means over these
  a.collisions += j["collisions"].get<int>();
  a.retries += j["retries"].get<int>();
  a.time += j["time_s"].get<double>();
  const double opt = j["optimal_length_m"].get<double>(), len = j["path_length_m"].get<double>();
  if (opt > 0 && len > 0) a.ratio += len / opt, ++a.ratio_n;
  if (docked)
    a.pos += j["position_error_m"].get<double>(), a.heading += j["heading_error_deg"].get<double>();
  // Driven length over the shortest possible on success: how far a method wanders. Records
  // without the bound (older ones) have no value: their optimum was no bound.
  const double shortest = j.value("shortest_possible_m", 0.0);
  if (docked && shortest > 0)
    a.driven_ratio += j["driven_length_m"].get<double>() / shortest, ++a.driven_n;
  a.local_minima += j.value("local_minima", 0);
  a.wall_follows += j.value("wall_follows", 0);
  const std::string status = j["status"].get<std::string>();
  a.trapped += status == "trapped";
  a.timeouts += status == "timeout";
  a.robot_collisions += j.value("collisions_robot_moving", 0);
  a.localization_error_max =
      std::max(a.localization_error_max, j.value("localization_error_max_m", 0.0));
  const std::string health = j.value("localization_status", std::string("ok"));
  a.localization_not_ok += health != "ok";
  a.docked_not_ok += docked && health != "ok";
  a.docked_lost += docked && health == "lost";
  a.localization_errors.push_back(j.value("localization_error_max_m", 0.0));
  a.not_ok_s += j.value("localization_not_ok_s", 0.0);
  a.stops += j.value("stops", 0);
  a.replans += j.value("replans", 0);
  a.recoveries += j.value("recoveries", 0);
  a.charging += j.value("charging", false);
  a.navigation.add(j);
  if (j.contains("failure") && j["failure"].is_string())
    if (const auto reason = robot::failure_reason_from_string(j["failure"].get<std::string>()))
      ++a.failed[static_cast<std::size_t>(*reason)];
}

/// "%.Nf" of a value, or an empty field when there is none (a mean over no docked episode).
std::string field(double value, int decimals, bool exists = true) {
  if (!exists) return "";
  char text[64];
  util::c_snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

/// The nearest-rank 95th percentile (0 of none).
double percentile95(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t rank =
      static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(v.size())));
  return v[std::max<std::size_t>(rank, 1) - 1];
}

std::string ConfigurationTally::row() const {
  const ConfigurationTally& a = *this;
  const auto [lo, hi] = wilson_interval(a.succeeded, a.n);
  const double n = static_cast<double>(a.n);
  auto whole = [](std::int64_t v) { return std::to_string(v); };
  const std::vector<std::string> cells = {
      whole(a.n),
      whole(a.succeeded),
      field(a.succeeded / n, 4),
      field(lo, 4),
      field(hi, 4),
      field(a.time / n, 2),
      field(a.ratio_n ? a.ratio / a.ratio_n : 0.0, 4, a.ratio_n > 0),
      field(a.docked ? 1000 * a.pos / a.docked : 0.0, 3, a.docked > 0),
      field(a.docked ? a.heading / a.docked : 0.0, 3, a.docked > 0),
      whole(a.collisions),
      field(a.retries / n, 3),
      field(a.driven_n ? a.driven_ratio / a.driven_n : 0.0, 4, a.driven_n > 0),
      field(a.local_minima / n, 3),
      field(a.wall_follows / n, 3),
      whole(a.trapped),
      whole(a.timeouts),
      whole(a.robot_collisions),
      field(1000 * a.localization_error_max, 2),
      whole(a.localization_not_ok),
      field(a.stops / n, 3),
      field(a.replans / n, 3),
      field(a.recoveries / n, 3),
      whole(a.charging),
      whole(a.docked_not_ok),
      whole(a.docked_lost),
      field(1000 * percentile95(a.localization_errors), 2),
      field(a.time > 0 ? a.not_ok_s / a.time : 0.0, 4)};
  std::string line;
  for (const std::string& c : cells) line += "," + c;
  line += a.navigation.csv_cells();
  for (std::int64_t count : a.failed) line += "," + std::to_string(count);
  return line;
}

/// summary.csv's header line.
std::string summary_header() {
  std::string out =
      "world,planner,controller,fault,episodes,succeeded,success_rate,ci95_low,ci95_high,"
      "mean_time_s,path_over_optimum,mean_position_error_mm,mean_heading_error_deg,collisions,"
      "mean_retries,driven_over_shortest,mean_local_minima,mean_wall_follows,trapped,timeouts,"
      "collisions_robot_moving,max_localization_error_mm,localization_not_ok,mean_stops,"
      "mean_replans,mean_recoveries,charging,docked_not_ok,docked_lost,p95_localization_error_mm,"
      "localization_not_ok_share";
  for (std::string_view column : kNavigationColumns) out += "," + std::string(column);
  for (robot::FailureReason reason : robot::kAllFailureReasons) {
    out += ",failed_";
    out += robot::to_string(reason);
  }
  return out;
}

/// The gate's columns of a row: its statistic, threshold and verdict ("pass", "fail", "not
/// gated"; a verdict over all worlds pooled says so).
std::string gate_cells(const std::string& world, const std::string& planner,
                       const std::string& controller, const std::string& fault,
                       const std::vector<ConfigurationVerdict>& verdicts, GateStatistic statistic) {
  for (const ConfigurationVerdict& v : verdicts) {
    if ((v.world != world && v.world != kAllWorlds) || v.planner != planner ||
        v.controller != controller || v.fault != fault)
      continue;
    if (!v.threshold) break;
    return std::string(",") + statistic_name(statistic) + "," + field(*v.threshold, 4) + "," +
           (v.passed ? "pass" : "fail") + (v.world == kAllWorlds ? " (all worlds pooled)" : "");
  }
  return ",,,not gated";
}

}  // namespace

std::string summary_csv(const std::vector<std::string>& lines, const Gate* gate) {
  std::map<std::tuple<std::string, std::string, std::string, std::string>, ConfigurationTally> acc;
  for (const std::string& line : lines) {
    const json j = json::parse(line);
    acc[{j["world"], j["planner"], j["controller"], j["fault"]}].add(j);
  }
  std::string out = summary_header();
  out += gate ? ",gate_statistic,gate_threshold,gate_verdict\n" : "\n";
  const std::vector<ConfigurationVerdict> verdicts =
      gate ? judge_configurations(lines, *gate) : std::vector<ConfigurationVerdict>{};
  for (const auto& [key, a] : acc) {
    const auto& [world, planner, controller, fault] = key;
    out += util::csv_field(world) + "," + util::csv_field(planner) + "," +
           util::csv_field(controller) + "," + util::csv_field(fault) + a.row();
    if (gate) out += gate_cells(world, planner, controller, fault, verdicts, gate->statistic);
    out += "\n";
  }
  return out;
}

std::string sweep_csv(const std::vector<std::string>& lines) {
  struct Acc {
    std::int64_t n = 0, docked = 0, charging = 0, collisions = 0, robot_collisions = 0,
                 failed_with_collision = 0;
    std::int64_t stops = 0, replans = 0;
    double time = 0, pos = 0;
  };
  std::string parameter;
  std::vector<std::string> order;  // values as first met
  std::map<std::string, Acc> acc;
  for (const std::string& line : lines) {
    const json j = json::parse(line);
    if (!j.contains("sweep_parameter")) continue;
    parameter = j["sweep_parameter"].get<std::string>();
    const std::string value = j["sweep_value"].get<std::string>();
    if (!acc.count(value)) order.push_back(value);
    Acc& a = acc[value];
    ++a.n;
    const bool docked = j["docked"].get<bool>();
    const int collisions = j["collisions"].get<int>();
    a.docked += docked;
    a.charging += j.value("charging", false);
    a.collisions += collisions;
    a.robot_collisions += j.value("collisions_robot_moving", 0);
    a.failed_with_collision += !docked && collisions > 0;
    a.stops += j.value("stops", 0);
    a.replans += j.value("replans", 0);
    a.time += j["time_s"].get<double>();
    if (docked) a.pos += j["position_error_m"].get<double>();
  }
  if (order.empty()) return "";
  // Numeric values in increasing order, so that the rows trace a curve.
  auto numeric = [](const std::string& s, double& v) {
    char* end = nullptr;
    v = util::c_strtod(s.c_str(), &end);
    return end && *end == '\0' && end != s.c_str();
  };
  double x = 0, y = 0;
  if (std::all_of(order.begin(), order.end(), [&](const std::string& s) { return numeric(s, x); }))
    std::stable_sort(order.begin(), order.end(), [&](const std::string& a, const std::string& b) {
      numeric(a, x);
      numeric(b, y);
      return x < y;
    });
  std::string out =
      "parameter,value,episodes,docked,success_rate,ci95_low,ci95_high,charging,collisions,"
      "collisions_robot_moving,"
      "failed_with_collision,mean_stops,mean_replans,mean_time_s,mean_position_error_mm\n";
  for (const std::string& value : order) {
    const Acc& a = acc[value];
    const auto [lo, hi] = wilson_interval(a.docked, a.n);
    char row[600];
    util::c_snprintf(
        row, sizeof row, ",%lld,%lld,%.4f,%.4f,%.4f,%lld,%lld,%lld,%lld,%.3f,%.3f,%.2f,%.3f\n",
        static_cast<long long>(a.n), static_cast<long long>(a.docked),
        static_cast<double>(a.docked) / a.n, lo, hi, static_cast<long long>(a.charging),
        static_cast<long long>(a.collisions), static_cast<long long>(a.robot_collisions),
        static_cast<long long>(a.failed_with_collision), static_cast<double>(a.stops) / a.n,
        static_cast<double>(a.replans) / a.n, a.time / a.n,
        a.docked ? 1000 * a.pos / a.docked : 0.0);
    out += util::csv_field(parameter) + "," + util::csv_field(value) + row;
  }
  return out;
}

}  // namespace plantsim::batch
