// Frames by the same layers as the run figure, at one canvas size, then ffmpeg if present.
#include "render/animation.h"

#include <cstdio>
#include <filesystem>
#include <vector>

#include "render/figure.h"
#include "render/layers.h"
#include "render/palette.h"
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
    Figure fig(o.width_px, o.height_px);
    const PixelTransform t =
        fig.world_panel(world.floor, {50, 40, o.width_px - 170.0, o.height_px - 40.0});
    GlCanvas& c = fig.canvas();
    std::vector<LegendEntry> legend;
    draw_floor(c, world);
    if (draw_obstacles(c, world)) legend.push_back({palette::kObstacle, "obstacle"});
    if (draw_unmapped(c, world)) legend.push_back({palette::kUnmapped, "not on map"});
    // Moving obstacles where the physics had them at this instant.
    std::vector<geom::Rect> boxes;
    for (const auto& track : run.moving_tracks) {
      std::size_t k = 0;
      while (k + 1 < track.t_s.size() && track.t_s[k + 1] <= run.trajectory[i].t_s) ++k;
      if (!track.boxes.empty()) boxes.push_back(track.boxes[k]);
    }
    if (draw_moving(c, world, run.trajectory[i].t_s, boxes))
      legend.push_back({palette::kMoving, "moving"});
    if (draw_trajectory_by_speed(c, run.trajectory, world.robot.max_speed_mps, i + 1, run.carries))
      legend.push_back({speed_swatch(run.trajectory, world.robot.max_speed_mps), "driven (speed)"});
    if (draw_plan(c, run.plan, palette::kPlan)) legend.push_back({palette::kPlan, "plan"});
    // What perception saw last before this instant.
    const episode::EpisodeResult::PerceptionSnapshot* seen = nullptr;
    for (const auto& snap : run.perception_log)
      if (snap.t_s <= run.trajectory[i].t_s) seen = &snap;
    if (seen) {
      draw_scan(c, seen->scan);
      draw_layer(c, seen->layer);
      draw_tracked(c, seen->tracked);
    }
    draw_start(c, world);
    draw_charger(c, world);
    draw_mapped_charger(c, world);
    draw_footprint(c, world.robot, run.trajectory[i].truth, palette::kRobot, 2.0);
    legend.push_back({palette::kRobot, "robot"});
    legend.push_back({palette::kStart, "start"});
    legend.push_back({palette::kCharger, "charger"});
    fig.legend(o.width_px - 150.0, 60, legend);
    fig.world_axes(world.floor, t);
    char title[160];
    util::c_snprintf(title, sizeof title, "%s  t = %.1f s  %s", world.name.c_str(),
                     run.trajectory[i].t_s,
                     std::string(controller::to_string(run.trajectory[i].phase)).c_str());
    fig.text(title, 50, 26, 16, palette::kAxis, Anchor::kLeft, true);
    char name[64];
    util::c_snprintf(name, sizeof name, "/frame_%04d.png", index++);
    writer.push(fig.finish(), frames + name);
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
