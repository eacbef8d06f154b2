// `plantsim run WORLD`: plan, drive and dock in the simulation; write the summary, the
// trajectory and the figure into the output folder. Exit 1 when the robot did not dock.
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/commands.h"
#include "app/episode_outputs.h"
#include "episode/episode_config_json.h"
#include "episode/episode_work.h"
#include "episode/run_episode.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "render/animation.h"
#include "util/atomic_file.h"
#include "util/fixed_text.h"
#include "worlds/known_keys.h"
#include "worlds/world_loader.h"

namespace plantsim::app {
namespace {

geom::Pose2 parse_pose(const std::string& text, const std::string& option) {
  geom::Pose2 p;
  char c1 = 0, c2 = 0;
  std::istringstream in(text);
  if (!(in >> p.x >> c1 >> p.y >> c2 >> p.yaw) || c1 != ',' || c2 != ',' || !in.eof() ||
      !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.yaw))
    throw std::invalid_argument(option + " expects x,y,yaw (metres, metres, radians), got '" +
                                text + "'");
  return p;
}

struct RunCommandOptions {
  std::string world;
  std::string planner = "vg";
  std::string out;
  std::uint64_t seed = 1;
  std::string start;
  std::string charger;
  std::string config;
  std::string travel;
  bool animate = false;
  bool undock = false;
  std::string scen;
  int query = 0;
};

/// One episode, its folder written: the exit code by its outcome.
int run_one(const RunCommandOptions& opt, const std::string& command) {
  worlds::PoseOverrides overrides;
  if (!opt.start.empty()) overrides.start = parse_pose(opt.start, "--start");
  if (!opt.charger.empty()) overrides.charger = parse_pose(opt.charger, "--charger");
  overrides.movingai_scen = opt.scen;
  overrides.movingai_query = opt.query;
  const worlds::World world = worlds::load_world(opt.world, overrides);
  episode::EpisodeConfig config =
      opt.config.empty() ? episode::EpisodeConfig{} : episode::load_episode_config(opt.config);
  auto p = planner::make_planner(opt.planner, planner::planner_input(world, true));
  episode::check_episode_work(world, config);
  // Every input is valid by now. The outputs are written into a staging folder beside the
  // destination (an unwritable place fails here, before the simulation) and moved into place
  // as a set: a rerun never mixes files of two runs.
  util::StagedFolder staged(
      opt.out.empty() ? "results/" + worlds::file_name_component(world.name) : opt.out,
      run_folder_names());
  const std::string& out_dir = staged.path();
  config.seed = opt.seed;
  // Read as the config file's `travel` is, by its one table of names: a third mode is not
  // taken for the field here.
  if (!opt.travel.empty())
    config = episode::parse_episode_config(nlohmann::json{{"travel", opt.travel}}.dump(),
                                           "--travel", config);
  if (opt.undock) config.docking.undock = true;
  if (opt.animate) config.scan_log_period_s = render::AnimationOptions{}.frame_every_s;
  const episode::EpisodeResult r = episode::run_episode(world, *p, config);

  const std::string line = command;
  std::string setting;
  if (!opt.config.empty())
    setting = "config " + std::filesystem::path(opt.config).filename().string();
  if (opt.seed != 1)
    setting += (setting.empty() ? "" : ", ") + std::string("seed ") + std::to_string(opt.seed);
  write_run_folder(world, r, config, out_dir, line, setting, opt.animate);
  staged.commit();
  // The units of every table: mm and degrees at the dock, seconds to a tenth.
  // A docking error only where it docked (else it was the distance to the charger).
  const bool at_dock = r.error_measured && (r.docked || r.caught);
  std::cout << world.name << ": " << episode::status_name(r) << ", position error "
            << (at_dock ? util::fixed(r.position_error_m * 1000, 1) + " mm" : "-")
            << ", heading error " << (at_dock ? util::fixed(r.heading_error_deg, 2) + " deg" : "-")
            << ", collisions " << r.collisions << ", retries " << r.retries << ", stops " << r.stops
            << ", replans " << r.replans << ", time " << util::fixed(r.time_s, 1) << " s -> "
            << staged.destination() << "\n";
  return r.succeeded() ? kExitOk : kExitFailed;
}

}  // namespace

std::function<int()> add_run_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "Simulate one docking episode and write its results");
  auto opt = std::make_shared<RunCommandOptions>();
  add_world_options(cmd, opt->world, opt->scen, opt->query);
  // Checked once the plugins are loaded (a plugin may add the planner named).
  cmd->add_option("--planner", opt->planner, "Planner name (plantsim info lists them)");
  cmd->add_option("--out", opt->out, "Output folder (default results/<world name>)");
  add_seed_option(cmd, opt->seed, "Random seed for noise");
  cmd->add_option("--start", opt->start, "Override the start pose: x,y,yaw");
  cmd->add_option("--charger", opt->charger, "Override the charger's docked pose: x,y,yaw");
  cmd->add_option("--config", opt->config,
                  "Controller, drive and sensing parameters (JSON, see docs/config.md)");
  cmd->add_option("--travel", opt->travel,
                  "path (follow the planner's path) or potential-field (seed 001; the plan is the "
                  "reference)")
      ->check(CLI::IsMember({"path", "potential-field"}));
  cmd->add_flag("--undock", opt->undock,
                "After charging starts, reverse to the staging pose (docking.undock)");
  cmd->add_flag("--animate", opt->animate,
                "Also write animation frames (and an MP4 when ffmpeg is installed)");
  auto plugin_files = std::make_shared<std::vector<std::string>>();
  add_plugin_option(cmd, *plugin_files);
  return [opt, cmd, plugin_files]() {
    load_plugins(*plugin_files);
    planner::planners().at(opt->planner);  // an unknown name: exit 2, the known ones listed
    return run_one(*opt, command_line(cmd));
  };
}

}  // namespace plantsim::app
