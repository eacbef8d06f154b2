// Files a run leaves in its output folder: summary.json (the metrics scripts read) and
// trajectory.csv (one row per simulation step). Written atomically.
#pragma once

#include <string>
#include <vector>

#include "sim/episode.h"

namespace plantsim::app {

std::string summary_json(const sim::EpisodeResult& r, const std::string& world_name,
                         const std::string& command_line);
std::string trajectory_csv(const sim::EpisodeResult& r);

/// The metrics table of reports: headers, and one row per episode.
std::vector<std::string> metric_headers();
std::vector<std::string> metric_row(const sim::EpisodeResult& r, const std::string& world_name);

}  // namespace plantsim::app
