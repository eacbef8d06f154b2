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
#include "controller/local_controller_registry.h"
#include "episode/episode_config_json.h"
#include "episode/run_episode.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "render/comparison_figure.h"
#include "render/png_io.h"
#include "render/report.h"
#include "util/atomic_file.h"
#include "util/made_by.h"
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
  std::vector<std::string> controllers;  ///< given: one panel per local controller instead
  std::string out;
  std::string title;
  std::string config;
  bool graph = false;
  bool plan_only = false;
};

/// One planner's panel: its plan alone (--plan-only), or the episode it drives.
/// With --controllers, `name` is the planner and `local` the panel's local controller.
render::ComparisonPanel compare_one(const std::string& name, const worlds::World& world,
                                    const CompareOptions& opt, const episode::EpisodeConfig& config,
                                    const std::string& local = "") {
  render::ComparisonPanel panel;
  panel.label = local.empty() ? name : local;
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
  if (!local.empty()) c.local_controller = local;
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

/// The panels' methods: the planners, or with --controllers the local controllers (each then
/// follows the one planner given, vg by default). A name twice drew the same method twice, as if
/// compared with itself: refused.
std::vector<std::string> compared_methods(CompareOptions& opt, bool planners_given) {
  const bool by_controller = !opt.controllers.empty();
  if (by_controller) {
    if (opt.plan_only) throw std::invalid_argument("--controllers: --plan-only drives nothing");
    if (!planners_given) opt.planners = {"vg"};
    if (opt.planners.size() != 1)
      throw std::invalid_argument("--controllers: name one planner for them to follow");
  }
  const std::vector<std::string>& methods = by_controller ? opt.controllers : opt.planners;
  for (std::size_t i = 0; i < methods.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (methods[i] == methods[j])
        throw std::invalid_argument(std::string(by_controller ? "--controllers" : "--planners") +
                                    ": '" + methods[i] + "' is listed twice");
  return methods;
}

std::string comparison_title(const CompareOptions& opt, const std::string& world) {
  if (!opt.title.empty()) return opt.title;
  return opt.controllers.empty() ? world + ": planners compared"
                                 : world + ": local controllers compared (" + opt.planners[0] + ")";
}

std::string comparison_notes(const CompareOptions& opt) {
  if (opt.plan_only)
    return "Plans from the start to the charger's docked position (the staging pose on ROS maps); "
           "nothing driven.";
  return opt.controllers.empty() ? "Each planner plans to the staging pose; the robot drives and "
                                   "docks in the simulation."
                                 : "The planner plans to the staging pose; each local controller "
                                   "follows that plan and the robot docks in the simulation.";
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
  cmd->add_option("--controllers", opt->controllers,
                  "Local controllers to compare instead (comma separated), each driving the one "
                  "planner given (default vg)")
      ->delimiter(',')
      ->check(CLI::IsMember(controller::local_controllers().names()));
  cmd->add_option("--out", opt->out, "Output folder (default results/<world name>_compare)");
  cmd->add_option("--title", opt->title, "Figure title");
  cmd->add_option("--config", opt->config, "Episode parameters (JSON)");
  cmd->add_flag("--graph", opt->graph, "Draw each planner's graph");
  cmd->add_flag("--plan-only", opt->plan_only, "Plan start to charger only; do not drive");
  return [opt, cmd]() {
    const bool by_controller = !opt->controllers.empty();
    const std::vector<std::string> methods = compared_methods(*opt, cmd->count("--planners") > 0);
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
    report.more_tables = {{"Navigation over the travel to the staging pose (docs/batch.md)",
                           navigation_headers(),
                           {}}};
    bool all_ok = true;
    for (const std::string& method : methods) {
      const std::string& name = by_controller ? opt->planners[0] : method;
      render::ComparisonPanel panel =
          compare_one(name, world, *opt, config, by_controller ? method : "");
      all_ok = all_ok && (opt->plan_only ? panel.run.plan_status == planner::PlanStatus::kOk
                                         : panel.run.succeeded());
      report.rows.push_back(metric_row(panel.run, world.name, panel.drove));
      if (panel.drove) report.more_tables[0].rows.push_back(navigation_row(panel.run, method));
      std::cout << method << ": " << episode::status_name(panel.run) << ", path "
                << panel.run.path_length_m << " m, plan "
                << panel.run.plan_stats.build_ms + panel.run.plan_stats.query_ms << " ms\n";
      panels.push_back(std::move(panel));
    }
    if (report.more_tables[0].rows.empty())
      report.more_tables.clear();  // plans alone drove nothing
    const std::string title = comparison_title(*opt, world.name);
    render::write_png(render::draw_comparison(world, panels, title), out_dir + "/comparison.png");
    // Stamped like every output: a comparison read later names the build that drew it.
    const util::MadeBy made_by;
    nlohmann::ordered_json data = comparison_json(world, title, command_line(cmd), panels);
    data["made_by"] = made_by.json();
    util::write_file_atomically(out_dir + "/comparison.json", data.dump(2) + "\n");
    report.made_by = made_by.text();
    report.title = title;
    report.command = command_line(cmd);
    report.figures = {{"comparison.png", title}};
    report.files = {"comparison.json"};
    report.notes = comparison_notes(*opt);
    render::write_report(report, out_dir + "/report.html");
    staged.commit();
    return all_ok ? kExitOk : kExitFailed;
  };
}

}  // namespace plantsim::app
