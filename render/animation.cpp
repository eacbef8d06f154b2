// Frames (plant_frame.h) at the animation's spacing, then ffmpeg if present.
#include "render/animation.h"

#include <cstdio>
#include <filesystem>
#include <vector>

#include "render/plant_frame.h"
#include "render/png_io.h"
#include "render/png_pipeline.h"
#include "util/c_number.h"
#include "util/process.h"

namespace plantsim::render {

std::string write_animation(const worlds::World& world, const episode::EpisodeResult& run,
                            const std::string& out_dir, const AnimationOptions& o) {
  const std::string frames = out_dir + "/frames";
  std::filesystem::create_directories(frames);
  int index = 0;
  double next = 0;
  PngPipeline writer(PngSettings::fast());  // encodes on the second core while frames are drawn
  for (std::size_t i = 0; i < run.trajectory.size(); ++i) {
    const bool last = i + 1 == run.trajectory.size();
    if (run.trajectory[i].t_s < next && !last) continue;
    next = run.trajectory[i].t_s + o.frame_every_s;
    PlantInstant at;
    at.t_s = run.trajectory[i].t_s;
    at.robot = run.trajectory[i].truth;
    at.phase = std::string(controller::to_string(run.trajectory[i].phase));
    at.trajectory = &run.trajectory;
    at.driven = i + 1;
    at.plan = run.plan;
    at.carries = &run.carries;
    // Moving obstacles where the physics had them at this instant.
    for (const auto& track : run.moving_tracks) {
      std::size_t k = 0;
      while (k + 1 < track.t_s.size() && track.t_s[k + 1] <= at.t_s) ++k;
      if (!track.boxes.empty()) at.moving.push_back(track.boxes[k]);
    }
    // What perception saw last before this instant.
    const episode::EpisodeResult::PerceptionSnapshot* seen = nullptr;
    for (const auto& snap : run.perception_log)
      if (snap.t_s <= at.t_s) seen = &snap;
    if (seen) {
      at.scan = &seen->scan;
      at.layer = seen->layer;
      at.tracked = seen->tracked;
    }
    char name[64];
    util::c_snprintf(name, sizeof name, "/frame_%04d.png", index++);
    writer.push(plant_frame(world, at, o.width_px, o.height_px), frames + name);
  }
  writer.close();
  // ffmpeg with an argument vector: the folder (a world's name by default) reaches it as one
  // argument, never through a shell.
  if (util::find_on_path("ffmpeg").empty()) return "";
  // Absolute paths: a folder named "-x" is not read as an option; a '%' in it is doubled, for
  // ffmpeg's frame pattern reads %d.
  const std::string dir = std::filesystem::absolute(out_dir).string();
  std::string pattern;
  for (char c : dir + "/frames/") pattern += c == '%' ? std::string("%%") : std::string(1, c);
  pattern += "frame_%04d.png";
  const std::string partial = dir + "/animation.mp4.tmp.mp4";
  const std::vector<std::string> argv = {
      "ffmpeg", "-y",    "-loglevel", "error",   "-framerate", std::to_string(o.frames_per_second),
      "-i",     pattern, "-pix_fmt",  "yuv420p", "-vf",        "pad=ceil(iw/2)*2:ceil(ih/2)*2",
      partial};
  std::error_code ec;
  if (util::run_program(argv) != 0) {
    std::filesystem::remove(partial, ec);
    return "";
  }
  std::filesystem::rename(partial, dir + "/animation.mp4", ec);
  return ec ? "" : "animation.mp4";
}

}  // namespace plantsim::render
