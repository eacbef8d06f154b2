// A replay of a run that plays in any browser without plugins: the run's data (world, plans,
// trajectory, moving obstacles) embedded as JSON in an HTML canvas player with play/pause, speed,
// a time slider, a clock and a legend, anti-aliased by the browser, zooming on the docking as
// the robot leaves travel. Its progress is exposed as data attributes (data-replay-frames,
// data-replay-time) so that a headless browser can check that it advances.
#pragma once

#include <string>

#include "episode/episode_result.h"

namespace plantsim::render {

struct ReplayOptions {
  int width_px = 960;
  int height_px = 600;
  int max_samples = 6000;  ///< the trajectory is thinned evenly in time beyond this
};

/// The player's HTML (a <section> with its canvas, controls and script), to embed in a report.
std::string replay_html(const worlds::World& world, const episode::EpisodeResult& run,
                        const ReplayOptions& options = {});

}  // namespace plantsim::render
