// An animation of a run: anti-aliased PNG frames (the map with the path so far, the robot,
// the moving obstacles where they were, a legend and the clock in the title), written with the
// fast PNG setting into DIR/frames/, and an MP4 made from them when ffmpeg is on the PATH (it
// is optional: plantsim never installs it; every report has the HTML replay instead).
#pragma once

#include <string>

#include "episode/episode_result.h"

namespace plantsim::render {

struct AnimationOptions {
  int width_px = 960;
  int height_px = 600;
  double frame_every_s = 1.0;  ///< simulated seconds between frames
  int frames_per_second = 15;  ///< playback rate of the MP4
};

/// Returns the movie's file name (relative to out_dir), or "" when ffmpeg is not available.
std::string write_animation(const worlds::World& world, const episode::EpisodeResult& run,
                            const std::string& out_dir, const AnimationOptions& options = {});

}  // namespace plantsim::render
