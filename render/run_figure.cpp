// Layout of the run figure and the time plots.
#include "render/run_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/layers.h"
#include "render/palette.h"

namespace plantsim::render {

std::string result_line(const sim::EpisodeResult& run) {
  char buf[200];
  if (run.trajectory.empty()) return run.status;
  std::snprintf(buf, sizeof buf, "%s, error %.1f cm / %.1f deg, %d collisions, %d retries, %.1f s", run.status.c_str(),
                100 * run.position_error_m, run.heading_error_deg, run.collisions, run.retries, run.time_s);
  std::string line = buf;
  if (run.travel != "path") {
    std::snprintf(buf, sizeof buf, ", %d minima, %d wall-follows", run.local_minima, run.wall_follows);
    line += buf;
  }
  return line;
}

std::string method_label(const sim::EpisodeResult& run) {
  if (run.travel == "path") return "planner " + run.planner;
  return run.travel + " (reference plan: " + run.planner + ")";
}

Image draw_run_figure(const worlds::World& world, const sim::EpisodeResult& run, const RunFigureOptions& o,
                      PixelTransform* transform_out) {
  Figure fig(o.width_px, o.height_px);
  const PixelBox panel{70, 76, o.width_px - 150.0, o.height_px - 50.0};
  const PixelTransform t = fig.world_panel(world.floor, panel);
  GlCanvas& c = fig.canvas();
  draw_floor(c, world);
  draw_obstacles(c, world);
  draw_unmapped(c, world);
  if (!o.graph_edges.empty()) draw_graph(c, o.graph_edges);
  const double t_end = run.trajectory.empty() ? 0.0 : run.trajectory.back().t_s;
  draw_moving(c, world, t_end, run.moving_final);
  if (!run.explored.empty()) c.polyline(run.explored, 5.0, palette::kExplored);
  draw_plan(c, run.plan);
  draw_target(c, world, run.trajectory);
  draw_wall_following(c, run.trajectory);
  draw_footprints(c, world.robot, run.trajectory, o.footprint_every_s);
  draw_estimate(c, run.trajectory);  // a band under the true path: its edges show where they agree
  draw_trajectory_by_speed(c, run.trajectory, world.robot.max_speed_mps);
  draw_scan(c, run.last_scan);
  draw_layer(c, run.layer_final);
  draw_events(c, run.events);
  draw_tracked(c, run.tracked_final);
  draw_start(c, world);
  if (!run.trajectory.empty()) draw_footprint(c, world.robot, run.trajectory.back().truth, palette::kRobot);
  draw_charger(c, world);
  draw_mapped_charger(c, world);
  fig.world_axes(world.floor, t);

  const std::string title = o.title.empty() ? world.name + "  |  " + method_label(run) : o.title;
  fig.text(title, 70, 26, 18, palette::kAxis, Anchor::kLeft, true);
  char sub[300];
  std::snprintf(sub, sizeof sub, "%s  |  planned %.2f m, driven %.2f m", result_line(run).c_str(), run.path_length_m,
                run.driven_length_m);
  fig.text(sub, 70, 46, 13, palette::kAxis);
  const double bar_x = o.width_px - 115.0;
  fig.colour_bar({bar_x, 90, bar_x + 16, 330}, 0.0, world.robot.max_speed_mps, "speed (m/s)");
  std::vector<LegendEntry> legend = {{palette::kObstacle, "obstacle"}, {palette::kInflation, "margin"},
                                     {palette::kPlan, "plan"},         {palette::kFootprint, "robot"},
                                     {palette::kStart, "start"},       {palette::kCharger, "charger"}};
  if (!world.unmapped.empty()) legend.push_back({palette::kUnmapped, "not on map"});
  if (worlds::differs_from_map(world)) legend.push_back({palette::kCharger, "map charger"});
  if (!world.moving.empty()) legend.push_back({palette::kMoving, "moving"});
  if (world.target) legend.push_back({palette::kTarget, "target"});
  if (!run.explored.empty()) legend.push_back({palette::kExplored, "explored"});
  if (run.travel != "path") legend.push_back({palette::kWallFollow, "wall following"});
  if (!o.graph_edges.empty()) legend.push_back({palette::kGraph, "graph"});
  if (!run.trajectory.empty()) legend.push_back({palette::kEstimate, "estimate"});
  if (!run.last_scan.explained.empty()) legend.push_back({palette::kScan, "last scan"});
  if (!run.last_scan.unexplained.empty()) legend.push_back({palette::kScanOffMap, "scan off map"});
  if (!run.tracked_final.empty()) legend.push_back({palette::kTracked, "tracked"});
  if (!run.layer_final.empty()) legend.push_back({palette::kLayer, "sensed layer"});
  using Kind = sim::EpisodeResult::Event::Kind;
  auto has = [&](Kind k) {
    return std::any_of(run.events.begin(), run.events.end(), [&](const auto& e) { return e.kind == k; });
  };
  if (has(Kind::kStop)) legend.push_back({palette::kStopMark, "stop"});
  if (has(Kind::kReplan)) legend.push_back({palette::kReplanMark, "replan"});
  if (has(Kind::kRecovery)) legend.push_back({palette::kRecoveryMark, "recovery"});
  fig.legend(bar_x - 10, 380, legend);
  if (transform_out) *transform_out = t;
  return fig.finish();
}

void write_run_figure(const worlds::World& world, const sim::EpisodeResult& run, const std::string& path,
                      const RunFigureOptions& options, const PngSettings& png) {
  write_png(draw_run_figure(world, run, options), path, png);
}

Image draw_time_plots(const worlds::World& world, const sim::EpisodeResult& run, int width_px, int height_px) {
  Figure fig(width_px, height_px);
  std::vector<double> t, cross, speed, distance, loc_error, loc_bound;
  for (const auto& s : run.trajectory) {
    t.push_back(s.t_s);
    loc_error.push_back(100.0 * geom::distance(s.truth.position(), s.estimate.position()));
    loc_bound.push_back(200.0 * s.position_sigma_m);
    cross.push_back(s.phase == controller::DockPhase::kTravel ? 100.0 * s.cross_track_m : NAN);
    speed.push_back(s.speed_mps);
    distance.push_back(geom::distance(s.truth.position(), world.charger.position()));
  }
  fig.text(world.name + "  |  " + method_label(run) + "  |  " + result_line(run), 70, 26, 16, palette::kAxis,
           Anchor::kLeft, true);
  const double left = 80, right = width_px - 40.0, h = (height_px - 60.0) / 4.0;
  fig.plot({left, 60 + 25, right, 60 + h - 25}, {{t, cross, palette::kPlan, "cross-track"}},
           "Cross-track error while travelling", "time (s)", "cm");
  fig.plot({left, 60 + h + 25, right, 60 + 2 * h - 25}, {{t, speed, palette::kTrajectory, "speed"}}, "Speed",
           "time (s)", "m/s");
  fig.plot({left, 60 + 2 * h + 25, right, 60 + 3 * h - 25}, {{t, distance, palette::kCharger, "distance"}},
           "Distance to the charger", "time (s)", "m");
  std::vector<Figure::Series> loc = {{t, loc_error, palette::kEstimate, "error"}};
  if (run.perception_mode == "sensors") loc.push_back({t, loc_bound, palette::kPlan, "2-sigma bound"});
  fig.plot({left, 60 + 3 * h + 25, right, 60 + 4 * h - 25}, loc,
           "Localisation error (true vs estimated position)" +
               std::string(run.perception_mode == "sensors" ? " and its 2-sigma bound" : ", oracle mode"),
           "time (s)", "cm");
  return fig.finish();
}

}  // namespace plantsim::render
