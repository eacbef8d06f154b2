// `plantsim plan WORLD`: plan from the world's start to its charger and print JSON.
#include <nlohmann/json.hpp>

#include <iomanip>
#include <iostream>

#include "app/commands.h"
#include "planner/planner.h"
#include "worlds/world_loader.h"

namespace plantsim::app {

std::function<int()> add_plan_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("plan", "Plan a path from the start to the charger; JSON on stdout");
  struct Options {
    std::string world;
    std::string planner = "vg";
    double inflate = -1;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("world", opt->world, "World file (plantsim JSON or a plain world)")->required();
  cmd->add_option("--planner", opt->planner, "Planner name")
      ->check(CLI::IsMember(planner::planner_names()));
  cmd->add_option("--inflate", opt->inflate,
                  "Inflation in metres (default: robot radius + the world's margin)")
      ->check(CLI::NonNegativeNumber);
  return [opt]() {
    const worlds::World world = worlds::load_world(opt->world);
    planner::PlannerInput input = planner::planner_input(world, false);
    if (opt->inflate >= 0) input.inflation_m = opt->inflate;
    auto p = planner::make_planner(opt->planner, input);
    const planner::PlanResult r = p->plan(world.start.position(), world.charger.position());
    nlohmann::json out;
    out["status"] = std::string(planner::to_string(r.status));
    out["planner"] = p->name();
    out["length"] = r.length;
    auto path = nlohmann::json::array();
    for (const auto& v : r.path) path.push_back({v.x, v.y});
    out["path"] = path;
    out["stats"] = {{"build_ms", r.stats.build_ms},     {"query_ms", r.stats.query_ms},
                    {"vertices", r.stats.vertices},     {"edges", r.stats.edges},
                    {"expanded", r.stats.expanded},     {"segment_tests", r.stats.segment_tests}};
    std::cout << std::setprecision(12) << out.dump() << "\n";
    return r.status == planner::PlanStatus::kOk ? kExitOk : kExitFailed;
  };
}

}  // namespace plantsim::app
