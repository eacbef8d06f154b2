// Layer drawing.
#include "render/layers.h"

#include <algorithm>
#include <cmath>

#include "render/colormap.h"
#include "render/palette.h"

namespace plantsim::render {

void draw_floor(GlCanvas& c, const worlds::World& w) {
  c.fill_rect(w.floor, palette::kFloor);
  // Grid every 1, 2, 5, 10 ... metres, whichever keeps lines at least 8 pixels apart.
  double step = 1.0;
  for (double s : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0})
    if (s * c.transform().scale >= 8.0) {
      step = s;
      break;
    }
  for (double x = std::ceil(w.floor.xmin / step) * step; x <= w.floor.xmax; x += step)
    c.polyline({{x, w.floor.ymin}, {x, w.floor.ymax}}, 1.0, palette::kGrid);
  for (double y = std::ceil(w.floor.ymin / step) * step; y <= w.floor.ymax; y += step)
    c.polyline({{w.floor.xmin, y}, {w.floor.xmax, y}}, 1.0, palette::kGrid);
}

void draw_obstacles(GlCanvas& c, const worlds::World& w) {
  const double inflation = w.planning_inflation_m();
  for (const auto& r : w.obstacles) {
    const geom::Rect m = r.inflated(inflation);
    c.fill_rect({std::max(m.xmin, w.floor.xmin), std::max(m.ymin, w.floor.ymin), std::min(m.xmax, w.floor.xmax),
                 std::min(m.ymax, w.floor.ymax)},
                palette::kInflation);
  }
  for (const auto& r : w.obstacles) c.fill_rect(r, palette::kObstacle);
}

namespace {

void outline(GlCanvas& c, const geom::Rect& r, double width_px, Rgb colour) {
  c.polyline({{r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}, {r.xmin, r.ymin}}, width_px, colour);
}

}  // namespace

void draw_unmapped(GlCanvas& c, const worlds::World& w) {
  // Diagonals x - y = k every 8 pixels, clipped to the rectangle.
  const double pitch = 8.0 / c.transform().scale;
  for (const geom::Rect& r : w.unmapped) {
    for (double k = std::ceil((r.xmin - r.ymax) / pitch) * pitch; k <= r.xmax - r.ymin; k += pitch) {
      // On x = y + k: y from max(ymin, xmin - k) to min(ymax, xmax - k).
      const double y0 = std::max(r.ymin, r.xmin - k), y1 = std::min(r.ymax, r.xmax - k);
      if (y1 > y0) c.polyline({{y0 + k, y0}, {y1 + k, y1}}, 1.2, palette::kUnmapped);
    }
    outline(c, r, 2.0, palette::kUnmapped);
  }
}

void draw_mapped_charger(GlCanvas& c, const worlds::World& w) {
  if (!worlds::differs_from_map(w)) return;
  const worlds::ChargerBody cb = worlds::charger_body(w, worlds::robot_map_charger(w));
  const Vec2 along = geom::rotate({cb.half_depth_m, 0}, cb.yaw), across = geom::rotate({0, cb.half_width_m}, cb.yaw);
  const Vec2 k = cb.center;
  c.polyline({k - along - across, k + along - across, k + along + across, k - along + across, k - along - across}, 1.5,
             palette::kCharger);
}

void draw_layer(GlCanvas& c, const std::vector<geom::Rect>& cells) {
  for (const geom::Rect& r : cells) outline(c, r, 2.5, palette::kLayer);
}

void draw_graph(GlCanvas& c, const std::vector<std::pair<Vec2, Vec2>>& edges) {
  for (const auto& [a, b] : edges) c.polyline({a, b}, 0.7, palette::kGraph);
}

void draw_charger(GlCanvas& c, const worlds::World& w) {
  const worlds::ChargerBody cb = worlds::charger_body(w);
  c.polyline({worlds::staging_pose(w).position(), cb.center}, 1.5, palette::kCharger);
  // Never smaller than a few pixels, so that it stays visible on large floors.
  const double min_half_m = 3.0 / c.transform().scale;
  c.fill_box(cb.center, std::max(cb.half_depth_m, min_half_m), std::max(cb.half_width_m, min_half_m), cb.yaw,
             palette::kCharger);
}

void draw_start(GlCanvas& c, const worlds::World& w) {
  c.fill_disk(w.start.position(), std::max(0.35 * w.robot.radius_m, 4.0 / c.transform().scale), palette::kStart);
}

void draw_moving(GlCanvas& c, const worlds::World& w, double t_s, const std::vector<geom::Rect>& boxes) {
  for (std::size_t i = 0; i < w.moving.size(); ++i) {
    const auto& m = w.moving[i];
    if (m.waypoints.size() > 1) c.polyline(m.waypoints, 1.0, palette::kMoving);
    c.fill_rect(i < boxes.size() ? boxes[i] : m.box_at(t_s), palette::kMoving);
  }
}

void draw_plan(GlCanvas& c, const std::vector<Vec2>& plan) { c.polyline(plan, 2.0, palette::kPlan); }

void draw_scan(GlCanvas& c, const sim::ScanView& scan) {
  // Dots of a few pixels whatever the scale.
  const Vec2 half_px{0.75, 0};
  for (const Vec2& p : scan.explained) {
    const Vec2 q = c.transform().to_pixel(p);
    c.pixel_line(q - half_px, q + half_px, 3.0, palette::kScan);
  }
  for (const Vec2& p : scan.unexplained) {
    const Vec2 q = c.transform().to_pixel(p);
    c.pixel_line(q - half_px, q + half_px, 4.0, palette::kScanOffMap);
  }
}

void draw_tracked(GlCanvas& c, const std::vector<controller::MovingBox>& boxes) {
  for (const auto& b : boxes) {
    const geom::Rect& r = b.box;
    outline(c, r, 1.5, palette::kTracked);
    if (geom::norm(b.velocity) > 0) c.polyline({r.center(), r.center() + b.velocity}, 1.5, palette::kTracked);
  }
}

void draw_estimate(GlCanvas& c, const std::vector<sim::TrajectorySample>& t) {
  std::vector<Vec2> path;
  path.reserve(t.size());
  for (const auto& s : t) path.push_back(s.estimate.position());
  if (path.size() > 1) c.polyline(path, 6.5, palette::kEstimate);
}

void draw_target(GlCanvas& c, const worlds::World& w, const std::vector<sim::TrajectorySample>& t) {
  if (!w.target) return;
  const auto& m = *w.target;
  if (m.waypoints.size() > 1) c.polyline(m.waypoints, 1.5, palette::kTarget);
  const Vec2 at = t.empty() ? m.position_at(0) : t.back().target;
  c.fill_box(at, 0.5 * m.width_m, 0.5 * m.height_m, 0.0, palette::kTarget);
}

void draw_wall_following(GlCanvas& c, const std::vector<sim::TrajectorySample>& t) {
  std::vector<Vec2> run;
  for (const auto& s : t) {
    if (s.wall_following) {
      run.push_back(s.truth.position());
    } else if (!run.empty()) {
      c.polyline(run, 11.0, palette::kWallFollow);
      run.clear();
    }
  }
  if (!run.empty()) c.polyline(run, 11.0, palette::kWallFollow);
}

void draw_trajectory_by_speed(GlCanvas& c, const std::vector<sim::TrajectorySample>& t, double max_speed_mps,
                              std::size_t upto) {
  const std::size_t n = std::min(upto, t.size());
  std::vector<Vec2> pts;
  std::vector<Rgb> colours;
  pts.reserve(n);
  colours.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    // Successive samples closer than half a pixel add nothing but draw calls.
    if (!pts.empty() && i + 1 < n && geom::distance(pts.back(), t[i].truth.position()) * c.transform().scale < 0.5) continue;
    if (!pts.empty()) colours.push_back(viridis(std::fabs(t[i].speed_mps) / max_speed_mps));
    pts.push_back(t[i].truth.position());
  }
  c.coloured_polyline(pts, colours, 3.0);
}

void draw_events(GlCanvas& c, const std::vector<sim::EpisodeResult::Event>& events) {
  using Kind = sim::EpisodeResult::Event::Kind;
  const double px = 1.0 / c.transform().scale;
  for (const auto& e : events) {
    // Nested sizes, so that a stop, a replan and a recovery at one place all show.
    const double r = e.kind == Kind::kStop ? 6 * px : e.kind == Kind::kReplan ? 9 * px : 12 * px;
    const Rgb colour = e.kind == Kind::kStop ? palette::kStopMark : e.kind == Kind::kReplan ? palette::kReplanMark
                                                                                          : palette::kRecoveryMark;
    c.ring(e.at, r, 2.5, colour);
  }
}

void draw_footprint(GlCanvas& c, const worlds::RobotSpec& robot, const geom::Pose2& pose, Rgb colour) {
  if (robot.rectangular()) {
    const double hl = 0.5 * robot.length_m, hw = 0.5 * robot.width_m;
    std::vector<Vec2> outline;
    for (Vec2 k : {Vec2{hl, hw}, Vec2{-hl, hw}, Vec2{-hl, -hw}, Vec2{hl, -hw}, Vec2{hl, hw}})
      outline.push_back(pose.position() + geom::rotate(k, pose.yaw));
    c.polyline(outline, 1.2, colour);
  } else {
    c.ring(pose.position(), robot.radius_m, 1.2, colour);
  }
  c.polyline({pose.position(), pose.position() + robot.front_extent_m() * pose.heading()}, 1.2, colour);
}

void draw_footprints(GlCanvas& c, const worlds::RobotSpec& robot, const std::vector<sim::TrajectorySample>& t,
                     double every_s) {
  double next = 0;
  for (const auto& s : t)
    if (s.t_s >= next) {
      draw_footprint(c, robot, s.truth, palette::kFootprint);
      next = s.t_s + every_s;
    }
}

}  // namespace plantsim::render
