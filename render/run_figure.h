// The figures of one run: the map figure (floor with axes, obstacles and margins, the plan,
// the driven path coloured by speed with a colour bar, footprints every few seconds and at
// the end, the charger with its approach axis, the start, a legend and a title with the
// result) and the time plots (cross-track error, speed, distance to the charger).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "render/figure.h"
#include "render/png_io.h"
#include "sim/episode.h"

namespace plantsim::render {

struct RunFigureOptions {
  int width_px = 1280;
  int height_px = 800;
  double footprint_every_s = 10.0;
  std::vector<std::pair<Vec2, Vec2>> graph_edges;  ///< drawn thin under the plan, if given
  std::string title;                               ///< default: world, planner and result
};

/// "planner vg", or "potential-field (reference plan: vg)".
std::string method_label(const sim::EpisodeResult& run);

/// Draws the run; `transform` receives the world-to-pixel mapping of the map panel.
Image draw_run_figure(const worlds::World& world, const sim::EpisodeResult& run, const RunFigureOptions& options = {},
                      PixelTransform* transform = nullptr);
void write_run_figure(const worlds::World& world, const sim::EpisodeResult& run, const std::string& path,
                      const RunFigureOptions& options = {}, const PngSettings& png = {});

/// Cross-track error, speed and distance to the charger against time, stacked.
Image draw_time_plots(const worlds::World& world, const sim::EpisodeResult& run, int width_px = 1280,
                      int height_px = 1000);

/// One-line result for titles: "docked, 0.4 cm / 0.1 deg, 0 collisions, 172.8 s".
std::string result_line(const sim::EpisodeResult& run);

}  // namespace plantsim::render
