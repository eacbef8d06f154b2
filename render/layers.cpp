// Layer drawing.
#include "render/layers.h"

#include <algorithm>
#include <cmath>

#include "geometry/predicates.h"
#include "planner/registry.h"
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

MarginShape margin_shape(const std::string& planner_name) {
  return planner::planner_can(planner_name, planner::capability::kRoundMargin)
             ? MarginShape::kRound
             : MarginShape::kSquare;
}

bool searches_a_mesh(const std::string& planner_name) {
  return planner::planner_can(planner_name, planner::capability::kSearchesAMesh);
}

bool draw_obstacles(GlCanvas& c, const worlds::World& w, MarginShape shape) {
  const double inflation = w.planning_inflation_m();
  auto fill_on_floor = [&](const geom::Rect& m) {
    c.fill_rect({std::max(m.xmin, w.floor.xmin), std::max(m.ymin, w.floor.ymin),
                 std::min(m.xmax, w.floor.xmax), std::min(m.ymax, w.floor.ymax)},
                palette::kInflation);
  };
  for (const auto& r : w.obstacles) {
    if (shape == MarginShape::kSquare || inflation <= 0) {
      fill_on_floor(r.inflated(inflation));
      continue;
    }
    // The rectangle grown by a disk: grown along x, along y, and a disk at each corner.
    fill_on_floor({r.xmin - inflation, r.ymin, r.xmax + inflation, r.ymax});
    fill_on_floor({r.xmin, r.ymin - inflation, r.xmax, r.ymax + inflation});
    // A corner on or past the floor's edge needs no disk: its part on the floor is covered.
    for (Vec2 k :
         {Vec2{r.xmin, r.ymin}, Vec2{r.xmax, r.ymin}, Vec2{r.xmax, r.ymax}, Vec2{r.xmin, r.ymax}})
      if (geom::in_open_rect(w.floor, k)) c.fill_disk(k, inflation, palette::kInflation);
  }
  for (const auto& r : w.obstacles) c.fill_rect(r, palette::kObstacle);
  return !w.obstacles.empty();
}

namespace {

void outline(GlCanvas& c, const geom::Rect& r, double width_px, Rgb colour) {
  c.polyline(
      {{r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}, {r.xmin, r.ymin}},
      width_px, colour);
}

}  // namespace

bool draw_unmapped(GlCanvas& c, const worlds::World& w) {
  // Diagonals x - y = k every 8 pixels, clipped to the rectangle.
  const double pitch = 8.0 / c.transform().scale;
  for (const geom::Rect& r : w.unmapped) {
    for (double k = std::ceil((r.xmin - r.ymax) / pitch) * pitch; k <= r.xmax - r.ymin;
         k += pitch) {
      // On x = y + k: y from max(ymin, xmin - k) to min(ymax, xmax - k).
      const double y0 = std::max(r.ymin, r.xmin - k), y1 = std::min(r.ymax, r.xmax - k);
      if (y1 > y0) c.polyline({{y0 + k, y0}, {y1 + k, y1}}, 1.2, palette::kUnmapped);
    }
    outline(c, r, 2.0, palette::kUnmapped);
  }
  return !w.unmapped.empty();
}

bool draw_mapped_charger(GlCanvas& c, const worlds::World& w) {
  if (!worlds::differs_from_map(w)) return false;
  const worlds::ChargerBody cb = worlds::charger_body(w, worlds::robot_map_charger(w));
  const Vec2 along = geom::rotate({cb.half_depth_m, 0}, cb.yaw),
             across = geom::rotate({0, cb.half_width_m}, cb.yaw);
  const Vec2 k = cb.center;
  c.polyline({k - along - across, k + along - across, k + along + across, k - along + across,
              k - along - across},
             1.5, palette::kCharger);
  return true;
}

bool draw_layer(GlCanvas& c, const std::vector<geom::Rect>& cells) {
  for (const geom::Rect& r : cells) outline(c, r, 2.5, palette::kLayer);
  return !cells.empty();
}

bool draw_graph(GlCanvas& c, const std::vector<std::pair<Vec2, Vec2>>& edges) {
  for (const auto& [a, b] : edges) c.polyline({a, b}, 0.7, palette::kGraph);
  return !edges.empty();
}

void draw_charger(GlCanvas& c, const worlds::World& w) {
  const worlds::ChargerBody cb = worlds::charger_body(w);
  c.polyline({worlds::staging_pose(w).position(), cb.center}, 1.5, palette::kCharger);
  // Never smaller than a few pixels, so that it stays visible on large floors.
  const double min_half_m = 3.0 / c.transform().scale;
  c.fill_box(cb.center, std::max(cb.half_depth_m, min_half_m),
             std::max(cb.half_width_m, min_half_m), cb.yaw, palette::kCharger);
}

void draw_start(GlCanvas& c, const worlds::World& w) {
  c.fill_disk(w.start.position(), std::max(0.35 * w.robot.radius_m, 4.0 / c.transform().scale),
              palette::kStart);
}

bool draw_moving(GlCanvas& c, const worlds::World& w, double t_s,
                 const std::vector<geom::Rect>& boxes) {
  for (std::size_t i = 0; i < w.moving.size(); ++i) {
    const auto& m = w.moving[i];
    if (m.waypoints.size() > 1) c.polyline(m.waypoints, 1.0, palette::kMoving);
    c.fill_rect(i < boxes.size() ? boxes[i] : m.box_at(t_s), palette::kMoving);
  }
  return !w.moving.empty();
}

std::string moving_tracks_label(const std::vector<episode::EpisodeResult::MovingTrack>& tracks) {
  constexpr double kMovedM = 0.01;  // less than this from where it began: it stood
  bool moved = false, stood = false;
  for (const auto& track : tracks) {
    if (track.boxes.empty()) continue;
    double farthest = 0;
    for (const geom::Rect& box : track.boxes)
      farthest = std::max(farthest, geom::distance(track.boxes.front().center(), box.center()));
    (farthest >= kMovedM ? moved : stood) = true;
  }
  return moved && stood ? "moving (swept) or parked" : moved ? "moving (swept)" : "parked";
}

bool draw_moving_tracks(GlCanvas& c,
                        const std::vector<episode::EpisodeResult::MovingTrack>& tracks) {
  bool drew = false;
  for (const auto& track : tracks) {
    if (track.boxes.empty()) continue;
    // The swept area as translucent boxes (one per pixel moved: a standing one is one box), then
    // the centre's track over it.
    const geom::Rect* last = nullptr;
    for (const geom::Rect& box : track.boxes) {
      if (last && geom::distance(last->center(), box.center()) * c.transform().scale < 1.0)
        continue;
      c.fill_rect(box, palette::kMoving, 0.12f);
      last = &box;
    }
    std::vector<Vec2> centre;
    centre.reserve(track.boxes.size());
    for (const geom::Rect& box : track.boxes) centre.push_back(box.center());
    c.polyline(centre, 1.5, palette::kMoving);
    outline(c, track.boxes.back(), 2.0, palette::kMoving);
    drew = true;
  }
  return drew;
}

bool draw_plan(GlCanvas& c, const std::vector<Vec2>& plan, Rgb colour, double width_px) {
  if (plan.size() < 2) return false;
  c.polyline(plan, width_px, colour);
  return true;
}

bool draw_dashed(GlCanvas& c, const std::vector<Vec2>& pts, double width_px, double dash_px,
                 Rgb colour) {
  if (pts.size() < 2) return false;
  const double dash = dash_px / c.transform().scale;
  double phase = 0;  // distance along the current dash-and-gap period
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double len = geom::distance(pts[i], pts[i + 1]);
    if (len <= 0) continue;
    const Vec2 dir = (1.0 / len) * (pts[i + 1] - pts[i]);
    double s = 0;
    while (s < len) {
      const double period_left = 2 * dash - phase;
      const double step = std::min(len - s, phase < dash ? dash - phase : period_left);
      if (phase < dash) c.polyline({pts[i] + s * dir, pts[i] + (s + step) * dir}, width_px, colour);
      s += step;
      phase = std::fmod(phase + step, 2 * dash);
    }
  }
  return true;
}

std::pair<bool, bool> draw_scan(GlCanvas& c, const robot::ScanView& scan) {
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
  return {!scan.explained.empty(), !scan.unexplained.empty()};
}

bool draw_tracked(GlCanvas& c, const std::vector<controller::MovingBox>& boxes) {
  for (const auto& b : boxes) {
    const geom::Rect& r = b.box;
    outline(c, r, 1.5, palette::kTracked);
    if (geom::norm(b.velocity) > 0)
      c.polyline({r.center(), r.center() + b.velocity}, 1.5, palette::kTracked);
  }
  return !boxes.empty();
}

bool draw_estimate(GlCanvas& c, const std::vector<episode::TrajectorySample>& t) {
  std::vector<Vec2> path;
  path.reserve(t.size());
  for (const auto& s : t) path.push_back(s.estimate.position());
  if (path.size() < 2) return false;
  c.polyline(path, 6.5, palette::kEstimate);
  return true;
}

bool draw_target(GlCanvas& c, const worlds::World& w,
                 const std::vector<episode::TrajectorySample>& t) {
  if (!w.target) return false;
  const auto& m = *w.target;
  if (m.waypoints.size() > 1) c.polyline(m.waypoints, 1.5, palette::kTarget);
  const Vec2 at = t.empty() ? m.position_at(0) : t.back().target;
  c.fill_box(at, 0.5 * m.width_m, 0.5 * m.height_m, 0.0, palette::kTarget);
  return true;
}

bool draw_wall_following(GlCanvas& c, const std::vector<episode::TrajectorySample>& t) {
  std::vector<Vec2> run;
  bool drew = false;
  for (const auto& s : t) {
    drew = drew || s.wall_following;
    if (s.wall_following) {
      run.push_back(s.truth.position());
    } else if (!run.empty()) {
      c.polyline(run, 11.0, palette::kWallFollow);
      run.clear();
    }
  }
  if (!run.empty()) c.polyline(run, 11.0, palette::kWallFollow);
  return drew;
}

bool draw_trajectory_by_speed(GlCanvas& c, const std::vector<episode::TrajectorySample>& t,
                              double max_speed_mps, std::size_t upto,
                              const std::vector<episode::EpisodeResult::Carry>& carries) {
  const std::size_t n = std::min(upto, t.size());
  std::vector<Vec2> pts;
  std::vector<Rgb> colours;
  pts.reserve(n);
  colours.reserve(n);
  bool drew = false;
  for (std::size_t i = 0; i < n; ++i) {
    // A carry between two samples ends a leg: the next is drawn apart (a kidnap is no driving).
    const bool carried = i > 0 && std::any_of(carries.begin(), carries.end(), [&](const auto& k) {
                           return k.t_s > t[i - 1].t_s && k.t_s <= t[i].t_s;
                         });
    if (carried) {
      c.coloured_polyline(pts, colours, 4.0);
      drew = drew || pts.size() > 1;
      pts.clear(), colours.clear();
    }
    // Successive samples closer than half a pixel add nothing but draw calls.
    if (!pts.empty() && i + 1 < n &&
        geom::distance(pts.back(), t[i].truth.position()) * c.transform().scale < 0.5)
      continue;
    if (!pts.empty()) colours.push_back(cividis(std::fabs(t[i].speed_mps) / max_speed_mps));
    pts.push_back(t[i].truth.position());
  }
  c.coloured_polyline(pts, colours, 4.0);
  return drew || pts.size() > 1;
}

bool draw_carries(GlCanvas& c, const std::vector<episode::EpisodeResult::Carry>& carries) {
  const double px = 1.0 / c.transform().scale;
  for (const auto& k : carries) {
    draw_dashed(c, {k.from.position(), k.to.position()}, 2.5, 9.0, palette::kCarry);
    c.ring(k.from.position(), 6 * px, 2.0, palette::kCarry);            // lifted
    c.fill_box(k.to.position(), 5 * px, 5 * px, 0.0, palette::kCarry);  // set down
  }
  return !carries.empty();
}

Rgb speed_swatch(const std::vector<episode::TrajectorySample>& t, double max_speed_mps) {
  if (t.empty()) return cividis(0);
  std::vector<double> speeds;
  speeds.reserve(t.size());
  for (const auto& s : t) speeds.push_back(std::fabs(s.speed_mps));
  std::nth_element(speeds.begin(), speeds.begin() + static_cast<std::ptrdiff_t>(speeds.size() / 2),
                   speeds.end());
  return cividis(speeds[speeds.size() / 2] / max_speed_mps);
}

Rgb event_colour(episode::EpisodeResult::Event::Kind kind) {
  using Kind = episode::EpisodeResult::Event::Kind;
  switch (kind) {
    case Kind::kStop:
      return palette::kStopMark;
    case Kind::kReplan:
      return palette::kReplanMark;
    case Kind::kRecovery:
      return palette::kRecoveryMark;
    case Kind::kCollision:
      return palette::kCollisionMark;
    case Kind::kRetry:
      return palette::kRetryMark;
    case Kind::kFailure:
      return palette::kFailureMark;
  }
  return palette::kAxis;
}

void draw_events(GlCanvas& c, const std::vector<episode::EpisodeResult::Event>& events) {
  using Kind = episode::EpisodeResult::Event::Kind;
  const double px = 1.0 / c.transform().scale;
  for (const auto& e : events) {
    if (e.kind == Kind::kCollision) {
      const Vec2 a{7 * px, 7 * px}, b{7 * px, -7 * px};
      c.polyline({e.at - a, e.at + a}, 3.0, palette::kCollisionMark);
      c.polyline({e.at - b, e.at + b}, 3.0, palette::kCollisionMark);
      continue;
    }
    if (e.kind == Kind::kFailure) {  // a diamond, larger than every ring, drawn last of all
      c.fill_box(e.at, 8 * px, 8 * px, M_PI / 4, palette::kFailureMark);
      continue;
    }
    // Nested sizes, so that a stop, a replan, a retry and a recovery at one place all show.
    const double r = e.kind == Kind::kStop     ? 6 * px
                     : e.kind == Kind::kReplan ? 9 * px
                     : e.kind == Kind::kRetry  ? 12 * px
                                               : 15 * px;
    c.ring(e.at, r, 2.5, event_colour(e.kind));
  }
}

void draw_footprint(GlCanvas& c, const worlds::RobotSpec& robot, const geom::Pose2& pose,
                    Rgb colour, double width_px) {
  // Never under 8 pixels across, heading mark included, so that it reads on a 100 m floor.
  const double grow = std::max(1.0, 4.0 / (c.transform().scale * std::max(robot.radius_m, 1e-9)));
  if (robot.rectangular()) {
    const double hl = 0.5 * robot.length_m * grow, hw = 0.5 * robot.width_m * grow;
    std::vector<Vec2> outline;
    for (Vec2 k : {Vec2{hl, hw}, Vec2{-hl, hw}, Vec2{-hl, -hw}, Vec2{hl, -hw}, Vec2{hl, hw}})
      outline.push_back(pose.position() + geom::rotate(k, pose.yaw));
    c.polyline(outline, width_px, colour);
  } else {
    c.ring(pose.position(), robot.radius_m * grow, width_px, colour);
  }
  c.polyline({pose.position(), pose.position() + grow * robot.front_extent_m() * pose.heading()},
             width_px, colour);
}

bool draw_footprints(GlCanvas& c, const worlds::RobotSpec& robot,
                     const std::vector<episode::TrajectorySample>& t, double every_s) {
  double next = 0;
  for (const auto& s : t)
    if (s.t_s >= next) {
      draw_footprint(c, robot, s.truth, palette::kFootprint);
      next = s.t_s + every_s;
    }
  return !t.empty();
}

}  // namespace plantsim::render
