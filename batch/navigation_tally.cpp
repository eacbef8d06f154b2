// The navigation metrics of a group of records (see the header).
#include "batch/navigation_tally.h"

#include <algorithm>
#include <numeric>

#include "util/c_number.h"
#include "util/csv.h"

namespace plantsim::batch {
namespace {

/// The record's number at `key`, if it holds one (null: not measured).
std::optional<double> number(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number()) return std::nullopt;
  return it->get<double>();
}

std::optional<double> mean(const std::vector<double>& v) {
  if (v.empty()) return std::nullopt;
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

/// The lower median (an episode's own value, not a mean of two).
std::optional<double> median(std::vector<double> v) {
  if (v.empty()) return std::nullopt;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>((v.size() - 1) / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

std::optional<double> largest(const std::vector<double>& v) {
  if (v.empty()) return std::nullopt;
  return *std::max_element(v.begin(), v.end());
}

}  // namespace

void NavigationTally::add(const nlohmann::json& j) {
  if (const auto c = number(j, "min_clearance_m"))
    min_clearance_ = min_clearance_ ? std::min(*min_clearance_, *c) : *c;
  auto collect = [&](const char* key, std::vector<double>& into) {
    if (const auto v = number(j, key)) into.push_back(*v);
  };
  collect("mean_clearance_m", mean_clearance_);
  collect("near_obstacle_share", near_share_);
  collect("rms_jerk_mps3", jerk_);
  collect("rms_angular_accel_radps2", angular_);
  collect("controller_ms_median", ms_median_);
  collect("controller_ms_p99", ms_p99_);
}

std::vector<std::optional<double>> NavigationTally::values() const {
  return {min_clearance_, mean(mean_clearance_), mean(near_share_), mean(jerk_),
          mean(angular_), median(ms_median_),    largest(ms_p99_)};
}

std::string NavigationTally::csv_cells() const {
  static constexpr int kDecimals[] = {4, 4, 4, 3, 3, 4, 4};
  std::string out;
  const std::vector<std::optional<double>> v = values();
  for (std::size_t i = 0; i < v.size(); ++i) {
    out += ",";
    if (!v[i]) continue;
    char text[64];
    util::c_snprintf(text, sizeof text, "%.*f", kDecimals[i], *v[i]);
    out += text;
  }
  return out;
}

nlohmann::json NavigationTally::json() const {
  nlohmann::json out = nlohmann::json::object();
  const std::vector<std::optional<double>> v = values();
  for (std::size_t i = 0; i < v.size(); ++i)
    out[std::string(kNavigationColumns[i])] = v[i] ? nlohmann::json(*v[i]) : nlohmann::json();
  return out;
}

std::string csv_without_wall_times(const std::string& csv) {
  std::vector<bool> keep;
  std::string out;
  for (std::size_t start = 0; start < csv.size();) {
    const std::size_t end = std::min(csv.find('\n', start), csv.size());
    const std::vector<std::string> cells = util::csv_split(csv.substr(start, end - start));
    if (keep.empty())  // the header
      for (const std::string& c : cells) keep.push_back(c.rfind(kWallTimePrefix, 0) != 0);
    std::string line;
    bool first = true;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (i < keep.size() && !keep[i]) continue;
      line += (first ? "" : ",") + util::csv_field(cells[i]);
      first = false;
    }
    out += line + "\n";
    start = end + 1;
  }
  return out;
}

}  // namespace plantsim::batch
