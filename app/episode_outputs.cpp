// Serialising an episode's metrics and trajectory.
#include "app/episode_outputs.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "episode/episode_config_json.h"
#include "episode/episode_json.h"
#include "render/animation.h"
#include "render/png_io.h"
#include "render/replay_html.h"
#include "render/report.h"
#include "render/run_figure.h"
#include "util/atomic_file.h"
#include "util/c_number.h"
#include "util/fingerprint.h"
#include "util/fixed_text.h"

namespace plantsim::app {

util::MadeBy run_made_by(const episode::EpisodeOutcome& r, const episode::EpisodeConfig& config) {
  util::MadeBy m;
  m.duration_s = r.wall_s;
  m.input = "config";
  m.input_hash = util::Fingerprint().add(episode::config_json(config)).hex();
  return m;
}

std::string summary_json(const episode::EpisodeResult& r, const std::string& world_name,
                         const std::string& command_line, const util::MadeBy* made_by) {
  nlohmann::ordered_json j;
  j["world"] = world_name;
  j["planner"] = r.planner;
  episode::add_episode_metrics(j, r);
  j["command"] = command_line;
  auto plan = nlohmann::ordered_json::array();
  for (const auto& v : r.plan) plan.push_back({v.x, v.y});
  j["plan"] = plan;
  if (!r.plan_note.empty()) j["plan_note"] = r.plan_note;
  if (made_by) j["made_by"] = made_by->json();
  if (r.thinning.any())  // a long episode's logs kept to their limits (docs/config.md)
    j["logs_thinned"] = {{"trajectory_every_control_periods", r.thinning.trajectory_every},
                         {"moving_tracks_every_s", 0.25 * r.thinning.moving_every},
                         {"perception_snapshots_every", r.thinning.snapshots_every},
                         {"controller_sketches_every_s", r.thinning.sketches_every},
                         {"events_dropped", r.thinning.events_dropped}};
  return j.dump(2) + "\n";
}

std::vector<std::string> metric_headers() {
  return {"world",
          "planner",
          "travel",
          "status",
          "position error (mm)",
          "heading error (deg)",
          "collisions",
          "retries",
          "stops",
          "replans",
          "local minima",
          "wall follows",
          "time (s)",
          "plan (ms)",
          "planned (m)",
          "driven (m)",
          "max cross-track (mm)"};
}

std::vector<std::string> metric_row(const episode::EpisodeOutcome& r, const std::string& world_name,
                                    bool drove) {
  using util::fixed;
  const std::string plan_ms = fixed(r.plan_stats.build_ms + r.plan_stats.query_ms, 2),
                    planned = fixed(r.path_length_m, 2);
  if (!drove) {  // a plan alone: nothing was driven, so nothing driven is measured
    const std::string none = "-";
    return {world_name, r.planner, none,    episode::status_name(r),
            none,       none,      none,    none,
            none,       none,      none,    none,
            none,       plan_ms,   planned, none,
            none};
  }
  // The docking error of an episode that never docked is no value (it was the distance to the
  // charger): "-"; the failure's banner says where it stopped.
  const bool at_dock = r.docked || r.caught;
  return {world_name,
          r.planner,
          r.travel,
          episode::status_name(r),
          at_dock ? fixed(1000 * r.position_error_m, 1) : "-",
          at_dock ? fixed(r.heading_error_deg, 2) : "-",
          std::to_string(r.collisions),
          std::to_string(r.retries),
          std::to_string(r.stops),
          std::to_string(r.replans),
          std::to_string(r.local_minima),
          std::to_string(r.wall_follows),
          fixed(r.time_s, 1),
          plan_ms,
          planned,
          fixed(r.driven_length_m, 2),
          fixed(1000 * r.max_cross_track_m, 0)};
}

std::vector<std::string> navigation_headers() {
  return {"run",
          "min clearance (m)",
          "mean clearance (m)",
          "share of time within 0.3 m",
          "RMS jerk (m/s^3)",
          "RMS angular accel. (rad/s^2)",
          "controller cycles",
          "controller median (ms)",
          "controller p99 (ms)"};
}

std::vector<std::string> navigation_row(const episode::EpisodeOutcome& r,
                                        const std::string& label) {
  auto value = [](double v, int decimals) {
    return std::isnan(v) ? std::string("-") : util::fixed(v, decimals);
  };
  return {label,
          value(r.min_clearance_m, 3),
          value(r.mean_clearance_m, 3),
          value(r.near_obstacle_share, 3),
          value(r.rms_jerk_mps3, 2),
          value(r.rms_angular_accel_radps2, 2),
          std::to_string(r.controller_cycles),
          value(r.controller_ms_median, 4),  // pure pursuit's step takes microseconds
          value(r.controller_ms_p99, 4)};
}

std::string trajectory_csv(const episode::EpisodeLog& r) {
  std::string out =
      "t_s,x_m,y_m,yaw_rad,est_x_m,est_y_m,est_yaw_rad,est_sigma_m,speed_mps,cross_track_m,phase,"
      "wall_following,target_x_m,target_y_m,est_status\n";
  char line[256];
  for (const auto& s : r.trajectory) {
    util::c_snprintf(line, sizeof line,
                     "%.4f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.4f,%.4f,%s,%d,%.4f,%.4f,%s\n",
                     s.t_s, s.truth.x, s.truth.y, s.truth.yaw, s.estimate.x, s.estimate.y,
                     s.estimate.yaw, s.position_sigma_m, s.speed_mps, s.cross_track_m,
                     std::string(controller::to_string(s.phase)).c_str(), s.wall_following ? 1 : 0,
                     s.target.x, s.target.y, std::string(robot::to_string(s.health)).c_str());
    out += line;
  }
  return out;
}

void write_run_folder(const worlds::World& world, const episode::EpisodeResult& r,
                      const episode::EpisodeConfig& config, const std::string& out_dir,
                      const std::string& line, const std::string& setting, bool animate) {
  const util::MadeBy made_by = run_made_by(r, config);
  util::write_file_atomically(out_dir + "/summary.json",
                              summary_json(r, world.name, line, &made_by));
  util::write_file_atomically(out_dir + "/trajectory.csv", trajectory_csv(r));
  render::RunFigureOptions figure;
  figure.setting = setting;
  figure.dock_tolerance_m = config.tolerance.lateral_tolerance_m;
  figure.dock_tolerance_deg = config.tolerance.heading_tolerance_rad * 180.0 / M_PI;
  render::write_run_figure(world, r, out_dir + "/run.png", figure);
  render::write_png(render::draw_time_plots(world, r), out_dir + "/timeplots.png");
  std::vector<render::ReportFigure> figures = {
      {"run.png",
       "The run: first and final plans over the driven path (coloured by speed), events, "
       "footprints, "
       "docking close-up"},
      {"timeplots.png",
       "Cross-track error, speed, distance to the charger, localisation error, shaded by phase"}};
  std::vector<std::string> files = {"summary.json", "trajectory.csv"};
  if (animate) {
    const std::string movie = render::write_animation(world, r, out_dir);
    files.push_back("frames/frame_0000.png");
    if (!movie.empty()) files.push_back(movie);
  }
  render::Report report;
  report.title = "plantsim run: " + world.name + (setting.empty() ? "" : " (" + setting + ")");
  report.command = line;
  report.headers = metric_headers();
  report.rows = {metric_row(r, world.name)};
  report.more_tables = {{"Navigation over the travel to the staging pose (docs/batch.md)",
                         navigation_headers(),
                         {navigation_row(r, world.name)}}};
  report.figures = figures;
  report.files = files;
  report.body_html = render::replay_html(world, r);
  if (r.failure)  // the verdict first: why, when, where
    report.banner_html =
        "<div class=\"banner fail\"><b>FAILED</b>: " +
        render::html_escape(std::string(robot::to_string(r.failure->reason))) +
        " at t = " + util::fixed(r.failure->time_s, 1) + " s, at (" +
        util::fixed(r.failure->pose.x, 2) + ", " + util::fixed(r.failure->pose.y, 2) + ") m" +
        (r.failure->detail.empty() ? "" : ": " + render::html_escape(r.failure->detail)) +
        " (docs/failures.md)</div>";
  report.made_by = made_by.text();
  render::write_report(report, out_dir + "/report.html");
}

std::vector<std::string> run_folder_names() {
  return {"summary.json", "trajectory.csv",          "run.png",      "timeplots.png",
          "report.html",  "frames/frame_[0-9]*.png", "animation.mp4"};
}

}  // namespace plantsim::app
