// A batch folder's report: summary.csv (and sweep.csv when the scenario sweeps a parameter),
// the charts (success with Wilson bars and gates, docking errors against their gates, driven
// length over the optimum and time to dock, success against the swept value), the plan figures
// and report.html with a readable table of the configurations.
#pragma once

#include <string>
#include <vector>

#include "batch/batch_spec.h"
#include "batch/episode_runner.h"
#include "util/made_by.h"
#include "worlds/world.h"

namespace plantsim::batch {

/// `made_by` stamps summary.json and report.html. `charts` false (--no-figures): no PNG at all.
/// `worlds_for_figures` null: no plan figures and no path overlays. `failures`: replayed failed
/// episodes for the gallery, each with the command that re-runs it from `scenario_path`.
/// Records of more than one build (batch/record_builds.h) are listed per build in summary.json
/// ("builds", "mixed_builds") and the report; the banner is then not green unless
/// `accept_mixed_builds`.
void write_batch_report(const std::vector<std::string>& jsonl_lines, const std::string& out_dir,
                        const std::string& title, const std::string& command,
                        const std::vector<worlds::World>* worlds_for_figures,
                        const std::vector<std::string>& planners, const Gate& gate, bool charts,
                        const util::MadeBy& made_by,
                        const std::vector<FailedEpisode>& failures = {},
                        const std::string& scenario_path = "", bool accept_mixed_builds = false);

}  // namespace plantsim::batch
