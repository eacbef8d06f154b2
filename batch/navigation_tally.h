// The navigation-benchmark metrics of a group of episode records (a summary row, a configuration
// of summary.json): the smallest minimum clearance of any episode, the mean of the episodes' mean
// clearances, of their shares of time near an obstacle, of their RMS jerks and angular
// accelerations, and the controller's compute time (the median of the episodes' medians, the
// largest of their 99th percentiles). Records that did not measure a metric (null, or older
// records without it) are left out of that metric; a metric no record measured has no value.
#pragma once

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace plantsim::batch {

/// The columns (summary.csv) and keys (summary.json) of the tally, in order.
inline constexpr std::array<std::string_view, 7> kNavigationColumns = {
    "min_clearance_m",
    "mean_clearance_m",
    "near_obstacle_share",
    "mean_rms_jerk_mps3",
    "mean_rms_angular_accel_radps2",
    "controller_ms_median",
    "controller_ms_p99_max"};

/// Wall-time columns and fields are named so: they differ from run to run (docs/batch.md), and
/// every comparison of two runs leaves them out.
inline constexpr std::string_view kWallTimePrefix = "controller_ms_";

class NavigationTally {
 public:
  void add(const nlohmann::json& record);
  /// Each of kNavigationColumns' values, in order; none where no record measured it.
  std::vector<std::optional<double>> values() const;
  /// The values as CSV fields (comma first each; empty where none).
  std::string csv_cells() const;
  /// The values as JSON (null where none), keyed by kNavigationColumns.
  nlohmann::json json() const;

 private:
  std::optional<double> min_clearance_;
  std::vector<double> mean_clearance_, near_share_, jerk_, angular_, ms_median_, ms_p99_;
};

/// CSV text without its wall-time columns (kWallTimePrefix), for comparing two runs' tables.
std::string csv_without_wall_times(const std::string& csv);

}  // namespace plantsim::batch
