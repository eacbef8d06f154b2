// The figures of one run: the map figure (floor with axes, obstacles and margins, the driven
// path coloured by speed on a fixed scale with the first and final plans drawn over it, events
// where they happened, moving obstacles' swept tracks with time ticks, footprints with heading,
// the charger, a legend of exactly what is drawn and a docking close-up) and the time plots
// (cross-track error, speed, distance to the charger, localisation error, shaded by phase).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "episode/episode_result.h"
#include "render/figure.h"
#include "render/png_io.h"

namespace plantsim::render {

struct RunFigureOptions {
  int width_px = 1280;
  int height_px = 800;
  double footprint_every_s = 10.0;
  std::vector<std::pair<Vec2, Vec2>> graph_edges;  ///< drawn thin under the plan, if given
  std::string title;                               ///< default: world, method and setting
  std::string setting;             ///< named in the default title ("config noisy.json")
  double dock_tolerance_m = 0.02;  ///< drawn in the docking close-up
  double dock_tolerance_deg = 2.0;
  double close_up_m = 1.5;  ///< the close-up shows this much of the last path
};

/// "planner vg", or "potential-field (reference plan: vg)".
std::string method_label(const episode::EpisodeOutcome& run);

/// Draws the run; `transform` receives the world-to-pixel mapping of the map panel.
Image draw_run_figure(const worlds::World& world, const episode::EpisodeResult& run,
                      const RunFigureOptions& options = {}, PixelTransform* transform = nullptr,
                      FigureLayout* layout = nullptr);
void write_run_figure(const worlds::World& world, const episode::EpisodeResult& run,
                      const std::string& path, const RunFigureOptions& options = {},
                      const PngSettings& png = {});

/// Cross-track error, speed and distance to the charger against time, stacked.
Image draw_time_plots(const worlds::World& world, const episode::EpisodeResult& run,
                      int width_px = 1280, int height_px = 1000, FigureLayout* layout = nullptr);

/// One-line result for titles: "docked, error 0.4 cm / 0.1 deg, 0 collisions, 0 retries, 172.8 s"
/// ("error n/a" where no docking error was measured: a pursuit, a run that never set off).
std::string result_line(const episode::EpisodeResult& run);
/// "planned 17.60 m, driven 32.80 m", or with replans "planned 17.60 m (final plan 24.10 m after 2
/// replans), driven ...".
std::string length_line(const episode::EpisodeResult& run);

}  // namespace plantsim::render
