// history.jsonl beside the dashboard: each time `summarize --html` lists a batch run it has not
// seen (its summary.json's made_by date), one line with its verdict, counts, commit and date; the
// dashboard draws each batch's last runs from it (a trend per gate, as CI dashboards do).
#pragma once

#include <string>
#include <vector>

#include "render/dashboard.h"

namespace plantsim::app {

/// Runs kept per batch on the dashboard's trend.
inline constexpr std::size_t kTrendRuns = 10;

/// Appends the batch links' current runs to `history_path` (those not yet in it) and fills each
/// batch link's trend with its last kTrendRuns runs. A line it cannot read is skipped, never fatal.
void update_history(const std::string& history_path, std::vector<render::DashboardLink>& links,
                    const std::vector<std::string>& summary_paths);

}  // namespace plantsim::app
