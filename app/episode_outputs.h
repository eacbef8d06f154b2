// Files a run leaves in its output folder: summary.json (the metrics scripts read),
// trajectory.csv (one row per control step), the run figure, the time plots and report.html
// with the replay. Written atomically.
#pragma once

#include <string>
#include <vector>

#include "episode/episode_config.h"
#include "episode/episode_result.h"
#include "util/made_by.h"

namespace plantsim::app {

/// `made_by`, when given, is written as "made_by" (util/made_by.h).
std::string summary_json(const episode::EpisodeResult& r, const std::string& world_name,
                         const std::string& command_line, const util::MadeBy* made_by = nullptr);
/// The stamp of a run: now, the episode's wall time, the hash of its whole config.
util::MadeBy run_made_by(const episode::EpisodeOutcome& r, const episode::EpisodeConfig& config);
std::string trajectory_csv(const episode::EpisodeLog& r);

/// The metrics table of reports: headers, and one row per episode.
std::vector<std::string> metric_headers();
/// The run's row under metric_headers(); `drove` false (a plan alone): "-" for what only driving
/// measures.
std::vector<std::string> metric_row(const episode::EpisodeOutcome& r, const std::string& world_name,
                                    bool drove = true);

/// The navigation metrics' table (docs/batch.md): headers, and one row per episode named `label`
/// ("-" where not measured; the controller's times are wall times of this machine).
std::vector<std::string> navigation_headers();
std::vector<std::string> navigation_row(const episode::EpisodeOutcome& r, const std::string& label);

/// Writes every file of a run into `out_dir` (a staging folder): `setting` is named in the run
/// figure's title; `animate` adds frames/ (and animation.mp4 when ffmpeg is installed).
void write_run_folder(const worlds::World& world, const episode::EpisodeResult& r,
                      const episode::EpisodeConfig& config, const std::string& out_dir,
                      const std::string& command_line, const std::string& setting, bool animate);

/// The names write_run_folder may write, for util::StagedFolder.
std::vector<std::string> run_folder_names();

}  // namespace plantsim::app
