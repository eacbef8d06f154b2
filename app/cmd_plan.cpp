// `plantsim plan WORLD`: plan from the world's start to its charger and print JSON.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>

#include "app/commands.h"
#include "planner/grid/grid_astar.h"
#include "planner/mesh/interval_planner.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "util/c_number.h"
#include "worlds/grid_map.h"
#include "worlds/world_error.h"
#include "worlds/world_loader.h"

namespace plantsim::app {
namespace {

// One line per scenario: "sx sy gx gy length" (-1 when there is no path; a query whose search
// passed its memory budget also says so on stderr, and the command exits 1). The visibility
// graph answers any-angle queries between lattice points (cell corners, the Polyanya
// convention); the grid planner answers octile queries between cell centres (MovingAI's).
int plan_scenarios(const std::string& map_path, const std::string& scen_path,
                   const std::string& planner_name, int landmarks,
                   std::size_t search_budget_bytes) {
  const worlds::GridMap map = worlds::load_movingai_map(map_path);
  const auto scenarios = worlds::load_movingai_scenarios(scen_path);
  // As `plantsim run --scen`: queries made for another map are refused, not answered with -1.
  for (std::size_t i = 0; i < scenarios.size(); ++i)
    if (scenarios[i].map_width != map.width || scenarios[i].map_height != map.height)
      throw worlds::WorldError(scen_path, "query " + std::to_string(i),
                               "a query for a " + std::to_string(scenarios[i].map_width) + " x " +
                                   std::to_string(scenarios[i].map_height) + " map, but " +
                                   map_path + " is " + std::to_string(map.width) + " x " +
                                   std::to_string(map.height));
  std::unique_ptr<planner::Planner> vg;
  if (planner_name != "grid") {
    planner::PlannerInput in;
    in.floor = {0, 0, static_cast<double>(map.width), static_cast<double>(map.height)};
    in.obstacles = worlds::merge_blocked_cells(map, worlds::blocked_for_anyangle);
    in.inflation_m = 0;
    if (landmarks > 0) in.options.set("landmarks", landmarks);
    in.search_budget_bytes = search_budget_bytes;
    vg = planner::make_planner(planner_name, in);
  }
  int exit_code = kExitOk;
  for (const auto& s : scenarios) {
    double length = -1;
    if (vg) {
      const auto r =
          vg->plan(worlds::lattice_point(map, s.sx, s.sy), worlds::lattice_point(map, s.gx, s.gy));
      if (r.status == planner::PlanStatus::kOk) length = r.length;
      if (r.status == planner::PlanStatus::kSearchLimit) {
        std::fprintf(stderr, "plantsim: plan: query %d %d %d %d: %s\n", s.sx, s.sy, s.gx, s.gy,
                     r.note.c_str());
        exit_code = kExitFailed;
      }
    } else {
      const auto r = planner::grid_astar(
          map.width, map.height,
          [&](int x, int y) { return worlds::passable_for_octile(map.at(x, y)); }, s.sx, s.sy, s.gx,
          s.gy);
      if (r.found) length = r.length;
    }
    std::printf("%d %d %d %d %.9g\n", s.sx, s.sy, s.gx, s.gy, length);
  }
  return exit_code;
}

struct PlanOptions {
  std::string world;
  std::string planner = "vg";
  double inflate = -1;
  int corner_steps = 1;
  std::string inflation = "square";
  bool snap = false;
  int landmarks = 0;
  std::vector<std::string> family_options;  ///< NAME=VALUE, the planner family's own
  int search_memory_mb = static_cast<int>(planner::kSearchMemoryBudgetBytes >> 20);
  std::string map, scen, goal;
};

void add_plan_options(CLI::App* cmd, PlanOptions& o) {
  auto* world_opt =
      cmd->add_option("world", o.world, "World file (plantsim JSON or a plain world)");
  auto* map_opt = cmd->add_option("--map", o.map, "MovingAI .map file (with --scen)");
  auto* scen_opt =
      cmd->add_option("--scen", o.scen, "MovingAI .scen file: one output line per query");
  map_opt->needs(scen_opt);
  scen_opt->needs(map_opt);
  world_opt->excludes(map_opt);
  cmd->add_option("--corner-steps", o.corner_steps,
                  "Corner inflation: 1 square (the document), more for a tighter staircase")
      ->transform(decimal_whole_number())
      ->check(CLI::Range(1, 16));
  cmd->add_option("--inflation", o.inflation,
                  "square (rectangles grown to rectangles, the document's; see --corner-steps) or "
                  "round (grown by a "
                  "disk, rounded corners: the disk robot's true optimum, segments and arcs; "
                  "planner vg-round)")
      ->check(CLI::IsMember({"square", "round"}));
  cmd->add_option("--goal", o.goal,
                  "docked (the charger's docked position; default for world files) or staging (the "
                  "staging pose "
                  "`run` plans to; default for ROS maps, whose charger stands against a wall "
                  "inside the planning inflation)")
      ->check(CLI::IsMember({"docked", "staging"}));
  cmd->add_option("--landmarks", o.landmarks,
                  "Planners interval and polyanya: this many landmarks for a stronger heuristic "
                  "(the same answers, fewer "
                  "nodes); "
                  "each costs one search over the whole map when the planner is built, so it pays "
                  "on many queries; "
                  "landmarks x mesh cells may not pass " +
                      std::to_string(planner::kLandmarkCellBudget) +
                      " (refused, with the most the map allows)")
      ->transform(decimal_whole_number())
      ->check(CLI::Range(0, 64));
  cmd->add_option("--search-memory-mb", o.search_memory_mb,
                  "Planners vg, interval, polyanya: a query whose search holds more than this "
                  "(MiB) stops with status \"search limit\" and exit 1 (default " +
                      std::to_string(planner::kSearchMemoryBudgetBytes >> 20) + ")")
      ->transform(decimal_whole_number())
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--option", o.family_options,
                  "NAME=VALUE: an option of the planner's family (grid: resolution_m; gcr, "
                  "gcr-shortcut: step_m; interval, polyanya: landmarks); repeatable; one the "
                  "family does not take is refused (docs/planners.md#options)");
  cmd->add_flag("--snap", o.snap,
                "Move a blocked start or charger to the nearest free point (reported)");
  cmd->add_option("--planner", o.planner, "Planner name")
      ->check(CLI::IsMember(planner::planner_names()));
  cmd->add_option("--inflate", o.inflate,
                  "Inflation in metres (default: robot radius + the world's margin)")
      ->check(CLI::NonNegativeNumber);
}

nlohmann::json plan_json(const planner::PlanResult& r, const std::string& planner_name,
                         const std::string& goal_kind, geom::Vec2 goal) {
  nlohmann::json out;
  out["status"] = std::string(planner::to_string(r.status));
  out["goal_kind"] = goal_kind;
  out["goal"] = {goal.x, goal.y};
  out["planner"] = planner_name;
  out["length"] = r.length;
  out["start_snapped"] = r.start_snapped;
  out["goal_snapped"] = r.goal_snapped;
  if (!r.note.empty()) out["note"] = r.note;
  auto path = nlohmann::json::array();
  for (const auto& v : r.path) path.push_back({v.x, v.y});
  out["path"] = path;
  if (!r.drive_path.empty()) {
    auto drive = nlohmann::json::array();
    for (const auto& v : r.drive_path) drive.push_back({v.x, v.y});
    out["drive_path"] = drive;
  }
  out["stats"] = {{"build_ms", r.stats.build_ms}, {"query_ms", r.stats.query_ms},
                  {"vertices", r.stats.vertices}, {"edges", r.stats.edges},
                  {"expanded", r.stats.expanded}, {"segment_tests", r.stats.segment_tests}};
  return out;
}

/// A world file: its start to its charger (or staging pose), as JSON on stdout.
int plan_world(PlanOptions& o) {
  if (o.landmarks > 0 && !planner::planner_can(o.planner, planner::capability::kSearchesAMesh))
    throw std::invalid_argument(
        "plan: --landmarks is for the mesh planners (interval, polyanya), not " + o.planner);
  if (!o.map.empty())
    return plan_scenarios(o.map, o.scen, o.planner, o.landmarks,
                          static_cast<std::size_t>(o.search_memory_mb) << 20);
  if (o.world.empty()) throw std::invalid_argument("plan: give a WORLD file, or --map with --scen");
  const worlds::World world = worlds::load_world(o.world);
  // A coverage plan covers the cells the charger's body leaves free and ends at the staging pose,
  // as `plantsim coverage` and an episode plan it: one world, one answer.
  const bool coverage = planner::planner_can(o.planner, planner::capability::kCoverage);
  planner::PlannerInput input = planner::planner_input(world, coverage);
  input.corner_steps = o.corner_steps;
  input.snap_to_free = o.snap;
  if (o.landmarks > 0) input.options.set("landmarks", o.landmarks);
  std::set<std::string> named;
  for (const std::string& given : o.family_options) {
    const std::size_t eq = given.find('=');
    char* end = nullptr;
    const double value = eq == std::string::npos ? 0 : util::c_strtod(given.c_str() + eq + 1, &end);
    if (eq == std::string::npos || eq == 0 || end == given.c_str() + eq + 1 || *end != '\0')
      throw std::invalid_argument("plan: --option takes NAME=VALUE with a number, not '" + given +
                                  "'");
    // The last of two would win unseen: a sweep script that appends its value would plan
    // with the first one's.
    if (!named.insert(given.substr(0, eq)).second)
      throw std::invalid_argument("plan: --option " + given.substr(0, eq) +
                                  " is given twice; give each option once");
    input.options.set(given.substr(0, eq), value);
  }
  input.search_budget_bytes = static_cast<std::size_t>(o.search_memory_mb) << 20;
  if (o.inflate >= 0) input.inflation_m = o.inflate;
  if (o.inflation == "round") {
    if (o.planner != "vg" && o.planner != "vg-round")
      throw std::invalid_argument(
          "plan: --inflation round is the visibility graph's (planner vg), not " + o.planner +
          "'s");
    if (o.corner_steps != 1)
      throw std::invalid_argument("plan: --corner-steps is for --inflation square");
    o.planner = "vg-round";
  }
  auto p = planner::make_planner(o.planner, input);
  const std::string ext = std::filesystem::path(o.world).extension().string();
  const bool ros_map = ext == ".yaml" || ext == ".yml";
  const std::string goal_kind =
      o.goal.empty() ? (ros_map || coverage ? "staging" : "docked") : o.goal;
  const geom::Vec2 goal =
      goal_kind == "staging" ? worlds::staging_pose(world).position() : world.charger.position();
  const planner::PlanResult r = p->plan(world.start.position(), goal);
  const nlohmann::json out = plan_json(r, p->name(), goal_kind, goal);
  std::cout << std::setprecision(12) << out.dump() << "\n";
  return r.status == planner::PlanStatus::kOk ? kExitOk : kExitFailed;
}

}  // namespace

std::function<int()> add_plan_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("plan", "Plan a path from the start to the charger; JSON on stdout");
  auto opt = std::make_shared<PlanOptions>();
  add_plan_options(cmd, *opt);
  return [opt]() { return plan_world(*opt); };
}

}  // namespace plantsim::app
