// Layout of the run figure (map panel, right column with colour bar, legend and the docking
// close-up) and of the time plots.
#include "render/run_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geometry/polyline.h"
#include "geometry/predicates.h"
#include "render/colormap.h"
#include "render/layers.h"
#include "render/method_marks.h"
#include "render/palette.h"
#include "util/c_number.h"
#include "util/fixed_text.h"

namespace plantsim::render {

std::string result_line(const episode::EpisodeResult& run) {
  char buf[200];
  if (run.trajectory.empty()) return episode::status_name(run);
  std::string error = "error n/a";
  if (run.error_measured) {
    util::c_snprintf(buf, sizeof buf, "error %.1f mm / %.1f deg", 1000 * run.position_error_m,
                     run.heading_error_deg);
    error = buf;
  }
  util::c_snprintf(buf, sizeof buf, "%s, %s, %d collisions, %d retries, %.1f s",
                   episode::status_name(run).c_str(), error.c_str(), run.collisions, run.retries,
                   run.time_s);
  std::string line = buf;
  if (run.travel != "path") {
    util::c_snprintf(buf, sizeof buf, ", %d minima, %d wall-follows", run.local_minima,
                     run.wall_follows);
    line += buf;
  }
  return line;
}

std::string length_line(const episode::EpisodeResult& run) {
  char buf[200];
  util::c_snprintf(buf, sizeof buf, "planned %.2f m", run.path_length_m);
  std::string line = buf;
  if (run.replans > 0 && run.plan != run.first_plan) {
    util::c_snprintf(buf, sizeof buf, " (final plan %.2f m after %d replan%s)",
                     geom::polyline_length(run.plan), run.replans, run.replans == 1 ? "" : "s");
    line += buf;
  } else if (run.plan != run.first_plan) {  // the robot's own route from the start
    util::c_snprintf(buf, sizeof buf, " (coastal route %.2f m)", geom::polyline_length(run.plan));
    line += buf;
  }
  util::c_snprintf(buf, sizeof buf, ", driven %.2f m", run.driven_length_m);
  return line + buf;
}

std::string method_label(const episode::EpisodeOutcome& run) {
  if (run.travel == "path") return "planner " + run.planner;
  return run.travel + " (reference plan: " + run.planner + ")";
}

namespace {

/// A tick period giving at most about ten ticks over `duration_s`.
double time_tick_period(double duration_s) {
  for (double p : {1.0, 2.0, 5.0, 10.0, 15.0, 30.0, 60.0, 120.0, 300.0, 600.0, 1200.0, 3600.0})
    if (duration_s / p <= 10.0) return p;
  return 7200.0;
}

/// The sample at or just after time t (the last if none).
const episode::TrajectorySample& sample_at(const std::vector<episode::TrajectorySample>& t,
                                           double time_s) {
  const auto it = std::lower_bound(t.begin(), t.end(), time_s,
                                   [](const auto& s, double v) { return s.t_s < v; });
  return it == t.end() ? t.back() : *it;
}

/// Time ticks on the driven path and on each moving obstacle's track at the same instants, so
/// that who was where when can be read off the picture.
void draw_time_ticks(Figure& fig, const episode::EpisodeResult& run, const PixelTransform& t) {
  if (run.trajectory.empty()) return;
  const double period = time_tick_period(run.trajectory.back().t_s);
  GlCanvas& c = fig.canvas();
  const double px = 1.0 / t.scale;
  for (double time = period; time <= run.trajectory.back().t_s; time += period) {
    char label[32];
    util::c_snprintf(label, sizeof label, "%.0f s", time);
    const Vec2 robot = sample_at(run.trajectory, time).truth.position();
    c.fill_disk(robot, 3.5 * px, palette::kRobot);
    const Vec2 rp = t.to_pixel(robot);
    fig.text_if_free(label, rp.x + 6, rp.y - 5, 11, palette::kRobot);
    for (const auto& track : run.moving_tracks) {
      if (track.t_s.empty() || time > track.t_s.back()) continue;
      const auto k = static_cast<std::size_t>(
          std::lower_bound(track.t_s.begin(), track.t_s.end(), time) - track.t_s.begin());
      const Vec2 m = track.boxes[std::min(k, track.boxes.size() - 1)].center();
      c.fill_disk(m, 3.5 * px, palette::kMoving);
      const Vec2 mp = t.to_pixel(m);
      fig.text_if_free(label, mp.x + 6, mp.y - 5, 11, palette::kOkabeBlue);
    }
  }
}

/// The last `length_m` of the driven path (by arc length from the end).
std::size_t close_up_start(const std::vector<episode::TrajectorySample>& t, double length_m) {
  double s = 0;
  std::size_t i = t.size() - 1;
  while (i > 0 && s < length_m) {
    s += geom::distance(t[i].truth.position(), t[i - 1].truth.position());
    --i;
  }
  return i;
}

/// A close-up's panel under its title line: `view` mapped into `box`, clipped to it, with the
/// floor and what stands near it (a thousand-obstacle plant need not be drawn twice). Returns
/// the panel's corners in pixels (lower left, upper right).
std::pair<Vec2, Vec2> open_close_up(Figure& fig, const worlds::World& world,
                                    const episode::EpisodeResult& run, const geom::Rect& view,
                                    const PixelBox& box) {
  GlCanvas& c = fig.canvas();
  const PixelTransform t = fig.world_panel(view, {box.left, box.top + 22, box.right, box.bottom});
  const Vec2 lo = t.to_pixel({view.xmin, view.ymin}), hi = t.to_pixel({view.xmax, view.ymax});
  c.set_clip(lo.x, hi.y, hi.x, lo.y);
  c.fill_rect(view, palette::kBackground);
  worlds::World near = world;
  const geom::Rect reach = view.inflated(world.planning_inflation_m());
  auto outside = [&](const geom::Rect& r) { return !geom::rects_overlap_open(r, reach); };
  near.obstacles.erase(std::remove_if(near.obstacles.begin(), near.obstacles.end(), outside),
                       near.obstacles.end());
  near.unmapped.erase(std::remove_if(near.unmapped.begin(), near.unmapped.end(), outside),
                      near.unmapped.end());
  draw_floor(c, near);
  draw_obstacles(c, near, margin_shape(run.planner));
  draw_unmapped(c, near);
  return {lo, hi};
}

/// Ends a close-up: the clip lifted and the panel framed.
void close_close_up(GlCanvas& c, Vec2 lo, Vec2 hi) {
  c.clear_clip();
  c.set_transform(PixelTransform{});
  c.pixel_polyline({{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}, {lo.x, lo.y}}, 1.0,
                   palette::kAxis);
}

/// The docking close-up: the last stretch of the path around the charger at a scale where the
/// tolerance is visible, with the tolerance band on the approach axis and the pose at contact.
void draw_docking_inset(Figure& fig, const worlds::World& world, const episode::EpisodeResult& run,
                        const RunFigureOptions& o, const PixelBox& box) {
  GlCanvas& c = fig.canvas();
  const auto& traj = run.trajectory;
  const std::size_t first = close_up_start(traj, o.close_up_m);
  geom::Rect view{world.charger.x, world.charger.y, world.charger.x, world.charger.y};
  auto include = [&](Vec2 p) {
    view = {std::min(view.xmin, p.x), std::min(view.ymin, p.y), std::max(view.xmax, p.x),
            std::max(view.ymax, p.y)};
  };
  for (std::size_t i = first; i < traj.size(); ++i) include(traj[i].truth.position());
  include(worlds::charger_body(world).center);
  // Square, with room for the footprint around everything.
  const double side = std::max(view.width(), view.height()) + 2.4 * world.robot.radius_m + 0.2;
  const Vec2 mid = view.center();
  view = {mid.x - 0.5 * side, mid.y - 0.5 * side, mid.x + 0.5 * side, mid.y + 0.5 * side};
  const auto [lo, hi] = open_close_up(fig, world, run, view, box);
  // The tolerance: the band of centres within it, 0.3 m along the approach axis up to the dock.
  const geom::Pose2& dock = world.charger;
  const Vec2 along = dock.heading(), across{-along.y, along.x};
  const Vec2 a = dock.position() - 0.3 * along, b = dock.position();
  const double tol = o.dock_tolerance_m;
  c.polyline(
      {a + tol * across, b + tol * across, b - tol * across, a - tol * across, a + tol * across},
      1.5, palette::kTolerance);
  draw_charger(c, world);
  draw_mapped_charger(c, world);
  std::vector<episode::TrajectorySample> tail(traj.begin() + static_cast<std::ptrdiff_t>(first),
                                              traj.end());
  draw_trajectory_by_speed(c, tail, world.robot.max_speed_mps, tail.size(), run.carries);
  if (run.error_measured) draw_footprint(c, world.robot, run.measured_pose, palette::kRobot, 2.0);
  close_close_up(c, lo, hi);
  char head[160];
  util::c_snprintf(head, sizeof head, "Docking, last %.1f m (band: +/-%.0f mm)", o.close_up_m,
                   1000 * tol);
  fig.text(head, box.left, box.top + 12, 13, palette::kAxis, Anchor::kLeft, true);
  char foot[160], gate[80];
  if (run.error_measured)
    util::c_snprintf(foot, sizeof foot, "%s: %.1f mm, %.1f deg off",
                     run.charging ? "at contact" : "at the end", 1000 * run.position_error_m,
                     run.heading_error_deg);
  else
    util::c_snprintf(foot, sizeof foot, "no docking error measured");
  util::c_snprintf(gate, sizeof gate, "gates: %.0f mm, %.0f deg", 1000 * tol, o.dock_tolerance_deg);
  fig.text_fitted(foot, box.left, lo.y + 16, 12, palette::kAxis, box.width());
  fig.text_fitted(gate, box.left, lo.y + 31, 12, palette::kAxis, box.width());
  fig.note_inset({box.left, box.top, box.right, lo.y + 35});
}

/// Every layer of the world panel, bottom to top, and the legend of what was drawn.
std::vector<LegendEntry> draw_world_layers(Figure& fig, const PixelTransform& t,
                                           const worlds::World& world,
                                           const episode::EpisodeResult& run,
                                           const RunFigureOptions& o) {
  GlCanvas& c = fig.canvas();
  std::vector<LegendEntry> legend;
  auto listed = [&](bool drawn, Rgb colour, const std::string& label,
                    Swatch swatch = Swatch::kBar) {
    if (drawn) legend.push_back({colour, label, swatch});
  };
  draw_floor(c, world);
  const MarginShape shape = margin_shape(run.planner);
  const bool obstacles = draw_obstacles(c, world, shape);
  listed(obstacles, palette::kObstacle, "obstacle");
  listed(obstacles && world.planning_inflation_m() > 0, palette::kInflation,
         shape == MarginShape::kRound ? "rounded margin" : "margin");
  listed(draw_unmapped(c, world), palette::kUnmapped, "not on map");
  listed(draw_graph(c, o.graph_edges), palette::kGraph,
         searches_a_mesh(run.planner) ? "mesh portals" : "graph");
  if (!run.moving_tracks.empty())
    listed(draw_moving_tracks(c, run.moving_tracks), palette::kMoving,
           moving_tracks_label(run.moving_tracks));
  else
    listed(draw_moving(c, world, run.trajectory.empty() ? 0.0 : run.trajectory.back().t_s,
                       run.moving_final),
           palette::kMoving, "moving");
  for (const LegendEntry& e : draw_walks_before_answer(c, run)) listed(true, e.colour, e.label);
  listed(draw_target(c, world, run.trajectory), palette::kTarget, "target");
  listed(draw_wall_following(c, run.trajectory), palette::kWallFollow, "wall following");
  listed(draw_footprints(c, world.robot, run.trajectory, o.footprint_every_s), palette::kFootprint,
         "robot / " + std::to_string(static_cast<int>(o.footprint_every_s)) + " s", Swatch::kRing);
  listed(draw_estimate(c, run.trajectory), palette::kEstimate, "estimated");
  if (draw_trajectory_by_speed(c, run.trajectory, world.robot.max_speed_mps, run.trajectory.size(),
                               run.carries))
    legend.push_back({speed_swatch(run.trajectory, world.robot.max_speed_mps), "driven (speed)"});
  // A kidnap's carry is no driving: dashed, with its time in the legend (issue 89).
  // "kidnap 30.5 s": short enough for a legend column, so the time is not cut off.
  std::string carried = "kidnap";
  for (std::size_t i = 0; i < run.carries.size(); ++i)
    carried += (i ? ", " : " ") + util::fixed(run.carries[i].t_s, 1);
  listed(draw_carries(c, run.carries), palette::kCarry, carried + " s", Swatch::kDashed);
  // The plans over the driven path, thin, so that neither hides the other.
  // Changed without a replan: the coastal route the robot chose over the planner's path.
  const bool changed = run.plan != run.first_plan;
  const bool replanned = changed && run.replans > 0;
  listed(changed && draw_dashed(c, run.first_plan, 1.6, 7.0, palette::kFirstPlan),
         palette::kFirstPlan, "first plan", Swatch::kDashed);
  listed(draw_plan(c, run.plan, palette::kPlan), palette::kPlan,
         replanned ? "final plan"
         : changed ? "coastal route"
                   : "plan");
  const auto [scan, scan_off] = draw_scan(c, run.last_scan);
  listed(scan, palette::kScan, "last scan");
  listed(scan_off, palette::kScanOffMap, "scan off map");
  listed(draw_layer(c, run.layer_final), palette::kLayer, "sensed layer", Swatch::kOutline);
  listed(draw_tracked(c, run.tracked_final), palette::kTracked, "tracked", Swatch::kOutline);
  draw_events(c, run.events);
  using Kind = episode::EpisodeResult::Event::Kind;
  for (const auto& named : {std::pair{Kind::kStop, "stop"},
                            {Kind::kReplan, "replan"},
                            {Kind::kRetry, "retry"},
                            {Kind::kRecovery, "recovery"},
                            {Kind::kCollision, "collision"},
                            {Kind::kFailure, "failure"}}) {
    const Kind kind = named.first;
    listed(std::any_of(run.events.begin(), run.events.end(),
                       [&](const auto& e) { return e.kind == kind; }),
           event_colour(kind), named.second, Swatch::kRing);
  }
  draw_start(c, world);
  listed(true, palette::kStart, "start", Swatch::kDot);
  if (!run.trajectory.empty())
    draw_footprint(c, world.robot, run.trajectory.back().truth, palette::kRobot, 2.0);
  draw_charger(c, world);
  listed(true, palette::kCharger, "charger");
  listed(draw_mapped_charger(c, world), palette::kCharger, "mapped charger", Swatch::kOutline);
  for (const LegendEntry& e : draw_plan_marks(fig, t, run.plan_trace.marks)) legend.push_back(e);
  if (!world.moving.empty()) draw_time_ticks(fig, run, t);
  return legend;
}

/// The title (world, method, setting, why it failed) and the result line under it.
void draw_titles(Figure& fig, const worlds::World& world, const episode::EpisodeResult& run,
                 const RunFigureOptions& o) {
  std::string title = world.name + "  |  " + method_label(run);
  if (!o.setting.empty()) title += "  |  " + o.setting;
  if (run.failure) {
    char failed[120];
    util::c_snprintf(failed, sizeof failed, "  |  failed: %s at %.1f s",
                     std::string(robot::to_string(run.failure->reason)).c_str(),
                     run.failure->time_s);
    title += failed;
  }
  fig.text_fitted(o.title.empty() ? title : o.title, 70, 26, 18, palette::kAxis, o.width_px - 90.0,
                  true);
  fig.text_fitted(result_line(run) + "  |  " + length_line(run), 70, 46, 13, palette::kAxis,
                  o.width_px - 90.0);
}

/// A pursuit ends at the target, not at the charger, and a robot that never came near the
/// charger has no docking to show.
/// Where a run failed away from the charger: a square of `kFailureView_m` around the failure's
/// pose, with what stood and moved there and the path through it (the whole map's scale would
/// make it a few pixels).
constexpr double kFailureView_m = 6.0;

void draw_failure_inset(Figure& fig, const worlds::World& world, const episode::EpisodeResult& run,
                        const PixelBox& box) {
  GlCanvas& c = fig.canvas();
  const robot::Failure& f = *run.failure;
  const double half = 0.5 * kFailureView_m;
  const geom::Rect view{f.pose.x - half, f.pose.y - half, f.pose.x + half, f.pose.y + half};
  const auto [lo, hi] = open_close_up(fig, world, run, view, box);
  draw_moving_tracks(c, run.moving_tracks);
  draw_plan(c, run.plan, palette::kPlan);
  draw_trajectory_by_speed(c, run.trajectory, world.robot.max_speed_mps, run.trajectory.size(),
                           run.carries);
  draw_carries(c, run.carries);
  draw_events(c, run.events);
  draw_footprint(c, world.robot, f.pose, palette::kRobot, 2.0);
  close_close_up(c, lo, hi);
  char head[160], foot[80];
  const std::string_view reason = robot::to_string(f.reason);
  util::c_snprintf(head, sizeof head, "%.*s at %.1f s", static_cast<int>(reason.size()),
                   reason.data(), f.time_s);
  util::c_snprintf(foot, sizeof foot, "%.0f m around where it failed:", kFailureView_m);
  fig.text_fitted(head, box.left, box.top + 12, 13, palette::kAxis, box.width(), true);
  fig.text_fitted(foot, box.left, lo.y + 16, 12, palette::kAxis, box.width());
  fig.text_fitted(f.detail, box.left, lo.y + 31, 12, palette::kAxis, box.width());
  fig.note_inset({box.left, box.top, box.right, lo.y + 35});
}

bool came_near_dock(const worlds::World& world, const episode::EpisodeResult& run) {
  return !run.trajectory.empty() &&
         (std::any_of(run.trajectory.begin(), run.trajectory.end(),
                      [](const auto& s) {
                        return s.phase != controller::DockPhase::kTravel &&
                               s.phase != controller::DockPhase::kFailed;
                      }) ||
          geom::distance(run.trajectory.back().truth.position(), world.charger.position()) < 3.0);
}

}  // namespace

Image draw_run_figure(const worlds::World& world, const episode::EpisodeResult& run,
                      const RunFigureOptions& o, PixelTransform* transform_out,
                      FigureLayout* layout_out) {
  Figure fig(o.width_px, o.height_px);
  const double column = o.width_px - 300.0;  // the right column: colour bar, legend, close-up
  const PixelBox panel{70, 76, column - 30, o.height_px - 50.0};
  const PixelTransform t = fig.world_panel(world.floor, panel);
  fig.clip_to_world(world.floor, t);
  const std::vector<LegendEntry> legend = draw_world_layers(fig, t, world, run, o);
  fig.world_axes(world.floor, t);
  draw_titles(fig, world, run, o);
  fig.colour_bar({column, 96, column + 240, 108}, 0.0, world.robot.max_speed_mps,
                 "speed (m/s), 0 to the robot's maximum");
  const int legend_columns = legend.size() > 9 ? 2 : 1;
  const PixelBox legend_box = fig.legend(column, 156, legend, legend_columns, 140);
  const double inset_top = std::max(legend_box.bottom + 12, o.height_px - 340.0);
  const PixelBox inset{column, inset_top, o.width_px - 20.0, o.height_px - 52.0};
  if (came_near_dock(world, run) && !world.target && inset_top + 150 < o.height_px)
    draw_docking_inset(fig, world, run, o, inset);
  else if (run.failure && inset_top + 150 < o.height_px)
    draw_failure_inset(fig, world, run, inset);
  if (transform_out) *transform_out = t;
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

void write_run_figure(const worlds::World& world, const episode::EpisodeResult& run,
                      const std::string& path, const RunFigureOptions& options,
                      const PngSettings& png) {
  write_png(draw_run_figure(world, run, options), path, png);
}

namespace {

/// The phases as shaded stretches of the time axis: travelling, docking (align and approach),
/// backing off to retry.
std::vector<Figure::Band> phase_bands(const std::vector<episode::TrajectorySample>& t) {
  using controller::DockPhase;
  auto kind = [](DockPhase p) {
    switch (p) {
      case DockPhase::kTravel:
        return 0;
      case DockPhase::kBackOff:
        return 2;
      default:
        return 1;
    }
  };
  const Rgb colours[3] = {palette::kPhaseTravel, palette::kPhaseDocking, palette::kPhaseBackOff};
  const char* labels[3] = {"travel", "docking", "back-off"};
  std::vector<Figure::Band> bands;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const int k = kind(t[i].phase);
    const double end = i + 1 < t.size() ? t[i + 1].t_s : t[i].t_s;
    if (!bands.empty() && bands.back().label == labels[k])
      bands.back().x1 = end;
    else
      bands.push_back({t[i].t_s, end, colours[k], labels[k]});
  }
  return bands;
}

}  // namespace

Image draw_time_plots(const worlds::World& world, const episode::EpisodeResult& run, int width_px,
                      int height_px, FigureLayout* layout_out) {
  Figure fig(width_px, height_px);
  std::vector<double> t, cross, speed, distance, loc_error, loc_bound;
  for (const auto& s : run.trajectory) {
    t.push_back(s.t_s);
    // In mm, as every table gives errors.
    loc_error.push_back(1000.0 * geom::distance(s.truth.position(), s.estimate.position()));
    loc_bound.push_back(2000.0 * s.position_sigma_m);
    // Cross-track error is a travelling measure; blank (not zero) while docking.
    cross.push_back(s.phase == controller::DockPhase::kTravel ? 1000.0 * s.cross_track_m : NAN);
    speed.push_back(s.speed_mps);
    distance.push_back(geom::distance(s.truth.position(), world.charger.position()));
  }
  fig.text(world.name + "  |  " + method_label(run), 70, 24, 16, palette::kAxis, Anchor::kLeft,
           true);
  fig.text(result_line(run), 70, 44, 13, palette::kAxis);
  const std::vector<Figure::Band> bands = phase_bands(run.trajectory);
  // The instants that explain a plot's jumps: each kidnap and the failure, on every plot.
  std::vector<Figure::PlotOptions::Marker> markers;
  for (const auto& k : run.carries) markers.push_back({k.t_s, palette::kCarry, "kidnap"});
  if (run.failure) markers.push_back({run.failure->time_s, palette::kFailureMark, "failure"});
  // Each plot's title sits above it, its tick numbers below: 56 px between plots holds both.
  const double left = 80, right = width_px - 40.0, top = 84, bottom = height_px - 48.0, gap = 56;
  const double h = (bottom - top + gap) / 4.0;
  auto box = [&](int i) { return PixelBox{left, top + i * h, right, top + (i + 1) * h - gap}; };
  Figure::PlotOptions first;
  first.bands = bands;
  first.markers = markers;
  first.legend = true;
  first.min_y_span = 10.0;
  first.note = "no travel";
  fig.plot(box(0), {{t, cross, palette::kTrajectory, "cross-track"}},
           "Cross-track error while travelling", "mm", first);
  Figure::PlotOptions plain;
  plain.bands = bands;
  plain.markers = markers;
  plain.min_y_span = 0.1;
  fig.plot(box(1), {{t, speed, palette::kTrajectory, "speed"}}, "Speed", "m/s", plain);
  fig.plot(box(2), {{t, distance, palette::kTrajectory, "distance"}}, "Distance to the charger",
           "m", plain);
  std::vector<Figure::Series> loc = {{t, loc_error, palette::kTrajectory, "error"}};
  if (run.perception_mode == "sensors")
    loc.push_back({t, loc_bound, palette::kPlan, "2-sigma bound"});
  Figure::PlotOptions last = plain;
  last.x_label = "time (s)";
  last.legend = true;
  last.min_y_span = 10.0;
  fig.plot(
      box(3), loc,
      "Localisation error" + std::string(run.perception_mode == "sensors" ? "" : " (oracle mode)"),
      "mm", last);
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

}  // namespace plantsim::render
