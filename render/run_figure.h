// The figure of one run: floor with a metre grid, inflated margins, obstacles, the plan, the
// driven trajectory, the start, the charger with its approach axis and the robot at the end.
#pragma once

#include <string>

#include "render/gl_canvas.h"
#include "sim/episode.h"

namespace plantsim::render {

struct RunFigureOptions {
  int width_px = 1280;
  int height_px = 800;
  int margin_px = 20;
};

/// The robot's outline and heading at a pose.
void draw_footprint(GlCanvas& canvas, const worlds::RobotSpec& robot, const geom::Pose2& pose, Rgb colour);

/// Draws the run into a new image; `transform` receives the world-to-pixel mapping used.
Image draw_run_figure(const worlds::World& world, const sim::EpisodeResult& run,
                      const RunFigureOptions& options = {}, PixelTransform* transform = nullptr);

void write_run_figure(const worlds::World& world, const sim::EpisodeResult& run,
                      const std::string& path, const RunFigureOptions& options = {});

}  // namespace plantsim::render
