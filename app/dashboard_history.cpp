// Reading and appending the dashboard's history.
#include "app/dashboard_history.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "util/atomic_file.h"
#include "util/input_file.h"
#include "worlds/json_input.h"

namespace plantsim::app {

namespace {

using nlohmann::json;

struct HistoryLine {
  std::string batch;  ///< the report's path as the dashboard links it
  render::TrendPoint point;
};

std::vector<HistoryLine> read_history(const std::string& path) {
  std::vector<HistoryLine> out;
  std::string text;
  try {
    text = util::read_input_file(path, 64u << 20);
  } catch (const std::exception&) {
    return out;  // none yet
  }
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    try {
      const json j = worlds::parse_json_input(line, path);
      out.push_back({j.at("batch").get<std::string>(),
                     {j.at("date").get<std::string>(), j.at("commit").get<std::string>(),
                      j.at("verdict").get<std::string>(), j.at("succeeded").get<std::int64_t>(),
                      j.at("episodes").get<std::int64_t>()}});
    } catch (const std::exception&) {
      // a torn or hand-edited line: skipped
    }
  }
  return out;
}

/// The batch's current run from its summary.json (nothing when it has no stamp).
std::optional<render::TrendPoint> current_run(const std::string& summary_path) {
  try {
    const json j =
        worlds::parse_json_input(util::read_input_file(summary_path, 64u << 20), summary_path);
    const json& m = j.at("made_by");
    return render::TrendPoint{m.at("date").get<std::string>(), m.at("commit").get<std::string>(),
                              j.value("verdict", std::string("not gated")),
                              j.value("succeeded", std::int64_t{0}),
                              j.value("episodes", std::int64_t{0})};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

void update_history(const std::string& history_path, std::vector<render::DashboardLink>& links,
                    const std::vector<std::string>& summary_paths) {
  std::vector<HistoryLine> history = read_history(history_path);
  std::string appended;
  for (std::size_t i = 0; i < links.size() && i < summary_paths.size(); ++i) {
    if (links[i].kind != "batch") continue;
    const std::optional<render::TrendPoint> now = current_run(summary_paths[i]);
    if (!now) continue;
    bool known = false;
    for (const HistoryLine& h : history)
      known = known || (h.batch == links[i].report && h.point.date == now->date);
    if (known) continue;
    history.push_back({links[i].report, *now});
    appended +=
        json{{"batch", links[i].report}, {"date", now->date},           {"commit", now->commit},
             {"verdict", now->verdict},  {"succeeded", now->succeeded}, {"episodes", now->episodes}}
            .dump() +
        "\n";
  }
  if (!appended.empty()) {
    std::string text;
    try {
      text = util::read_input_file(history_path, 64u << 20);
    } catch (const std::exception&) {
    }
    if (!text.empty() && text.back() != '\n') text += '\n';  // a torn last line stays its own
    util::write_file_atomically(history_path, text + appended);
  }
  for (render::DashboardLink& l : links) {
    if (l.kind != "batch") continue;
    for (const HistoryLine& h : history)
      if (h.batch == l.report) l.trend.push_back(h.point);
    if (l.trend.size() > kTrendRuns) l.trend.erase(l.trend.begin(), l.trend.end() - kTrendRuns);
  }
}

}  // namespace plantsim::app
