// `plantsim compare WORLD --planners a,b,...`: every planner on the same world, driven and
// docked, drawn side by side at the same scale; with --graph each panel shows its graph (the
// source document's Fig. 5 / Fig. 6 when the planners are vg and vg-traditional).
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "app/commands.h"
#include "app/episode_outputs.h"
#include "episode/episode_config_json.h"
#include "episode/run_episode.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "render/comparison_figure.h"
#include "render/png_io.h"
#include "render/report.h"
#include "util/atomic_file.h"
#include "worlds/known_keys.h"
#include "worlds/world_loader.h"

namespace plantsim::app {

namespace {

constexpr const char* kFieldEntry = "potential-field";

struct CompareOptions {
  std::string scen;
  int query = 0;
  std::string world;
  std::vector<std::string> planners = {"vg", "vg-traditional", "grid"};
  std::string out;
  std::string title;
  std::string config;
  bool graph = false;
  bool plan_only = false;
};

/// One planner's panel: its plan alone (--plan-only), or the episode it drives.
render::ComparisonPanel compare_one(const std::string& name, const worlds::World& world,
                                    const CompareOptions& opt,
                                    const episode::EpisodeConfig& config) {
  render::ComparisonPanel panel;
  panel.label = name;
  panel.drove = !opt.plan_only;
  if (opt.plan_only) {
    auto p = planner::make_planner(name, planner::planner_input(world, false));
    // As `plan`: a ROS map's charger stands against a wall inside the planning inflation, so
    // its plans end at the staging pose (`run` plans there for every world).
    const std::string ext = std::filesystem::path(opt.world).extension().string();
    const bool ros_map = ext == ".yaml" || ext == ".yml";
    const planner::PlanResult r =
        p->plan(world.start.position(),
                ros_map ? worlds::staging_pose(world).position() : world.charger.position());
    panel.run.planner = name;
    panel.run.status = episode::EpisodeStatus::kPlannerAnswer;
    panel.run.plan_status = r.status;
    panel.run.plan = r.path;
    panel.run.path_length_m = r.length;
    panel.run.plan_stats = r.stats;
    if (opt.graph) panel.graph_edges = p->graph_edges();
    return panel;
  }
  // The potential field has no plan of its own: the visibility graph's is its reference.
  const bool field = name == kFieldEntry;
  auto p = planner::make_planner(field ? "vg" : name, planner::planner_input(world, true));
  episode::EpisodeConfig c = config;
  if (field) c.travel = "potential-field";
  panel.run = episode::run_episode(world, *p, c);
  if (opt.graph) panel.graph_edges = p->graph_edges();
  return panel;
}

/// The figure's numbers, for whoever quotes them.
nlohmann::ordered_json comparison_json(const worlds::World& world, const std::string& title,
                                       const std::string& command,
                                       const std::vector<render::ComparisonPanel>& panels) {
  nlohmann::ordered_json data;
  data["world"] = world.name;
  data["title"] = title;
  data["command"] = command;
  for (const auto& panel : panels) {
    const planner::PlanStats& st = panel.run.plan_stats;
    data["panels"].push_back({{"label", panel.label},
                              {"status", episode::status_name(panel.run)},
                              {"path_length_m", panel.run.path_length_m},
                              {"build_ms", st.build_ms},
                              {"query_ms", st.query_ms},
                              {"vertices", st.vertices},
                              {"edges_evaluated", st.edges},
                              {"segment_tests", st.segment_tests},
                              {"expanded", st.expanded},
                              {"graph_edges_drawn", panel.graph_edges.size()}});
  }
  if (panels.size() == 2) data["differences"] = render::what_differs(panels[0], panels[1]);
  return data;
}

}  // namespace

std::function<int()> add_compare_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("compare", "Several planners on one world, side by side, with a report");
  auto opt = std::make_shared<CompareOptions>();
  add_world_options(cmd, opt->world, opt->scen, opt->query);
  std::vector<std::string> choices = planner::planner_names();
  choices.push_back(kFieldEntry);
  cmd->add_option("--planners", opt->planners,
                  "Planners to compare (comma separated); potential-field drives by seed 001's "
                  "field instead")
      ->delimiter(',')
      ->check(CLI::IsMember(choices));
  cmd->add_option("--out", opt->out, "Output folder (default results/<world name>_compare)");
  cmd->add_option("--title", opt->title, "Figure title");
  cmd->add_option("--config", opt->config, "Episode parameters (JSON)");
  cmd->add_flag("--graph", opt->graph, "Draw each planner's graph");
  cmd->add_flag("--plan-only", opt->plan_only, "Plan start to charger only; do not drive");
  return [opt, cmd]() {
    // One panel per planner: a name twice drew the same method twice, as if compared with itself.
    for (std::size_t i = 0; i < opt->planners.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (opt->planners[i] == opt->planners[j])
          throw std::invalid_argument("--planners: '" + opt->planners[i] + "' is listed twice");
    worlds::PoseOverrides poses;
    poses.movingai_scen = opt->scen;
    poses.movingai_query = opt->query;
    const worlds::World world = worlds::load_world(opt->world, poses);
    const episode::EpisodeConfig config =
        opt->config.empty() ? episode::EpisodeConfig{} : episode::load_episode_config(opt->config);
    util::StagedFolder staged(
        opt->out.empty() ? "results/" + worlds::file_name_component(world.name) + "_compare"
                         : opt->out,
        {"comparison.png", "comparison.json", "report.html"});
    const std::string& out_dir = staged.path();
    std::vector<render::ComparisonPanel> panels;
    render::Report report;
    report.headers = metric_headers();
    bool all_ok = true;
    for (const std::string& name : opt->planners) {
      render::ComparisonPanel panel = compare_one(name, world, *opt, config);
      all_ok = all_ok && (opt->plan_only ? panel.run.plan_status == planner::PlanStatus::kOk
                                         : panel.run.succeeded());
      report.rows.push_back(metric_row(panel.run, world.name, panel.drove));
      std::cout << name << ": " << episode::status_name(panel.run) << ", path "
                << panel.run.path_length_m << " m, plan "
                << panel.run.plan_stats.build_ms + panel.run.plan_stats.query_ms << " ms\n";
      panels.push_back(std::move(panel));
    }
    const std::string title = opt->title.empty() ? world.name + ": planners compared" : opt->title;
    render::write_png(render::draw_comparison(world, panels, title), out_dir + "/comparison.png");
    util::write_file_atomically(
        out_dir + "/comparison.json",
        comparison_json(world, title, command_line(cmd), panels).dump(2) + "\n");
    report.title = title;
    report.command = command_line(cmd);
    report.figures = {{"comparison.png", title}};
    report.files = {"comparison.json"};
    report.notes = opt->plan_only ? "Plans from the start to the charger's docked position (the "
                                    "staging pose on ROS maps); nothing driven."
                                  : "Each planner plans to the staging pose; the robot drives and "
                                    "docks in the simulation.";
    render::write_report(report, out_dir + "/report.html");
    staged.commit();
    return all_ok ? kExitOk : kExitFailed;
  };
}

}  // namespace plantsim::app
