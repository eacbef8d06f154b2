// results/index.html as a dashboard: one table of every run (a thumbnail linking to its report,
// status, errors, setting, links to each figure), then the comparisons, batches and coverage
// runs, each a row with its thumbnail and a link. Thumbnails are the figures themselves scaled
// by the browser to a fixed width: no full-size image walls.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace plantsim::render {

struct DashboardRun {
  std::string folder;  ///< relative to the dashboard
  std::string world, setting, status;
  bool succeeded = false;
  std::vector<std::string> cells;  ///< the metric cells, in the order of the headers
  std::vector<std::string>
      figures;        ///< figure files inside the folder (the first is the thumbnail)
  std::string stale;  ///< why its files may not be this build's (empty: made by it)
};

/// One earlier run of a batch, from the dashboard's history file (history.jsonl beside it).
struct TrendPoint {
  std::string date, commit, verdict;  ///< verdict: "passed", "failed" or "not gated"
  std::int64_t succeeded = 0, episodes = 0;
};

struct DashboardLink {
  std::string kind;  ///< "comparison", "batch", "tune", "coverage", "chart", "report"
  std::string title;
  std::string report;             ///< relative to the dashboard
  std::string thumbnail;          ///< relative to the dashboard, may be empty
  std::string line;               ///< one line said about it (from its files)
  std::string verdict;            ///< a batch's: "passed", "failed" or "not gated" (summary.json)
  std::string stale;              ///< why its files may not be this build's (empty: made by it)
  std::vector<TrendPoint> trend;  ///< a batch's runs, oldest first, the last one its current run
};

/// `made_by`: the dashboard's own stamp (util/made_by.h), under the title; a run or link that is
/// `stale` is flagged beside its status.
std::string dashboard_html(const std::string& title, const std::vector<std::string>& metric_headers,
                           const std::vector<DashboardRun>& runs,
                           const std::vector<DashboardLink>& links,
                           const std::string& made_by = "");

}  // namespace plantsim::render
