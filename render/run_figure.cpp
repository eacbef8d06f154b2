// Layer order matters: margins under obstacles, plan under trajectory, robot on top.
#include "render/run_figure.h"

#include <algorithm>
#include <cmath>

#include "render/palette.h"
#include "render/png_io.h"

namespace plantsim::render {

void draw_footprint(GlCanvas& canvas, const worlds::RobotSpec& robot, const geom::Pose2& pose, Rgb colour) {
  if (robot.rectangular()) {
    const double hl = 0.5 * robot.length_m, hw = 0.5 * robot.width_m;
    std::vector<geom::Vec2> outline;
    for (geom::Vec2 k : {geom::Vec2{hl, hw}, geom::Vec2{-hl, hw}, geom::Vec2{-hl, -hw}, geom::Vec2{hl, -hw}, geom::Vec2{hl, hw}})
      outline.push_back(pose.position() + geom::rotate(k, pose.yaw));
    canvas.polyline(outline, 1.5, colour);
  } else {
    canvas.ring(pose.position(), robot.radius_m, 1.5, colour);
  }
  canvas.polyline({pose.position(), pose.position() + robot.front_extent_m() * pose.heading()}, 1.5, colour);
}

Image draw_run_figure(const worlds::World& world, const sim::EpisodeResult& run,
                      const RunFigureOptions& o, PixelTransform* transform_out) {
  GlCanvas canvas(o.width_px, o.height_px);
  canvas.clear(palette::kBackground);
  const PixelTransform t = PixelTransform::fit(world.floor, o.margin_px, o.margin_px,
                                               o.width_px - o.margin_px, o.height_px - o.margin_px,
                                               o.height_px);
  canvas.set_transform(t);
  canvas.fill_rect(world.floor, palette::kFloor);
  const double grid_px = 1.0;
  for (double x = std::ceil(world.floor.xmin); x <= world.floor.xmax; x += 1.0)
    canvas.polyline({{x, world.floor.ymin}, {x, world.floor.ymax}}, grid_px, palette::kGrid);
  for (double y = std::ceil(world.floor.ymin); y <= world.floor.ymax; y += 1.0)
    canvas.polyline({{world.floor.xmin, y}, {world.floor.xmax, y}}, grid_px, palette::kGrid);

  const double inflation = world.planning_inflation_m();
  for (const auto& r : world.obstacles) canvas.fill_rect(r.inflated(inflation), palette::kInflation);
  for (const auto& r : world.obstacles) canvas.fill_rect(r, palette::kObstacle);

  const worlds::ChargerBody cb = worlds::charger_body(world);
  const geom::Pose2 staging = worlds::staging_pose(world);
  canvas.polyline({staging.position(), cb.center}, 1.5, palette::kCharger);

  // Moving obstacles: their scripted route, and where they were at the end.
  const double t_end = run.trajectory.empty() ? 0.0 : run.trajectory.back().t_s;
  for (const auto& m : world.moving) {
    if (m.waypoints.size() > 1) canvas.polyline(m.waypoints, 1.0, palette::kMoving);
    canvas.fill_rect(m.box_at(t_end), palette::kMoving);
  }

  canvas.polyline(run.plan, 2.0, palette::kPlan);
  std::vector<geom::Vec2> driven;
  driven.reserve(run.trajectory.size());
  for (const auto& s : run.trajectory) driven.push_back(s.truth.position());
  canvas.polyline(driven, 3.0, palette::kTrajectory);

  canvas.fill_disk(world.start.position(), 0.35 * world.robot.radius_m + 0.1, palette::kStart);
  if (!run.trajectory.empty()) {
    const geom::Pose2 end = run.trajectory.back().truth;
    draw_footprint(canvas, world.robot, end, palette::kRobot);
  }
  // The charger last, and never smaller than a few pixels, so that it stays visible.
  const double min_half_m = 3.0 / t.scale;
  canvas.fill_box(cb.center, std::max(cb.half_depth_m, min_half_m), std::max(cb.half_width_m, min_half_m),
                  cb.yaw, palette::kCharger);
  if (transform_out) *transform_out = t;
  return canvas.read();
}

void write_run_figure(const worlds::World& world, const sim::EpisodeResult& run,
                      const std::string& path, const RunFigureOptions& options) {
  write_png(draw_run_figure(world, run, options), path);
}

}  // namespace plantsim::render
