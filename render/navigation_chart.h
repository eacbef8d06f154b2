// The batch report's navigation chart: per method, each episode's smallest clearance of the true
// footprint to the true obstacles (against the 0.3 m near line), its RMS jerk, and the local
// controller's median compute time per cycle (wall time of this machine), as strips of dots.
#pragma once

#include <vector>

#include "render/batch_charts.h"

namespace plantsim::render {

/// Three strip panels side by side; episodes that did not measure a value leave it out.
Image draw_navigation_chart(const std::vector<EpisodeOutcome>& episodes, int width_px = 1400,
                            FigureLayout* layout = nullptr);

}  // namespace plantsim::render
