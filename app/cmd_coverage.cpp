// `plantsim coverage WORLD`: seed 004's full-coverage methods side by side on one work area
// (CHNN, exact and greedy sub-region orders, and cell-by-cell coverage), with the document's
// metrics; --drive also sweeps and docks in the simulation and measures the cells the robot's
// centre actually passed through. Exit 1 when a plan leaves a reachable cell uncovered.
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "worlds/known_keys.h"
#include "planner/coverage/coverage_planner.h"
#include "render/coverage_figure.h"
#include "render/png_io.h"
#include "render/report.h"
#include "sim/episode_config_json.h"
#include "util/atomic_file.h"
#include "worlds/world_loader.h"

namespace plantsim::app {
namespace {

// Reachable cells the robot's centre passed through.
double driven_coverage(const planner::CoverageGrid& g, const std::vector<geom::Vec2>& trajectory, planner::Cell start) {
  const std::vector<bool> reach = g.reachable(start);
  std::vector<bool> seen(reach.size(), false);
  for (const geom::Vec2& p : trajectory)
    if (const auto c = g.cell_at(p)) seen[g.index(*c)] = true;
  int reachable = 0, covered = 0;
  for (std::size_t i = 0; i < reach.size(); ++i) reachable += reach[i], covered += reach[i] && seen[i];
  return reachable ? static_cast<double>(covered) / reachable : 0.0;
}

}  // namespace

std::function<int()> add_coverage_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("coverage", "Seed 004: full-coverage methods compared on one work area");
  struct Options {
    std::string world, out, config;
    double cell_m = 2.0;
    bool drive = false;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("world", opt->world, "World file")->required();
  cmd->add_option("--out", opt->out, "Output folder (default results/<world>_coverage)");
  cmd->add_option("--cell", opt->cell_m, "Cell size (m)")->check(CLI::Range(0.2, 100.0));
  cmd->add_option("--config", opt->config, "Episode parameters for --drive (JSON)");
  cmd->add_flag("--drive", opt->drive, "Also sweep and dock in the simulation");
  return [opt, cmd]() {
    const worlds::World world = worlds::load_world(opt->world);
    sim::EpisodeConfig config = opt->config.empty() ? sim::EpisodeConfig{} : sim::load_episode_config(opt->config);
    util::StagedFolder staged(opt->out.empty() ? "results/" + worlds::file_name_component(world.name) + "_coverage" : opt->out,
                              {"coverage.png", "coverage.json", "report.html"});
    const std::string& out_dir = staged.path();
    planner::PlannerInput input = planner::planner_input(world, true);
    input.coverage_cell_m = opt->cell_m;

    std::vector<std::unique_ptr<planner::CoveragePlanner>> planners;
    std::vector<render::CoveragePanel> panels;
    nlohmann::ordered_json summary;
    summary["world"] = world.name;
    summary["command"] = command_line(cmd);
    bool all_covered = true;
    render::Report report;
    report.headers = {"method", "regions", "coverage (%)", "repetition (%)", "turns", "dead ends", "path (m)",
                      "order cost", "exact cost", "driven coverage (%)", "episode"};
    for (const char* name : {"coverage", "coverage-exact", "coverage-greedy", "coverage-cells"}) {
      planners.push_back(std::make_unique<planner::CoveragePlanner>(input, planner::coverage_method(name)));
      planner::CoveragePlanner& p = *planners.back();
      const planner::PlanResult r = p.plan(world.start.position(), worlds::staging_pose(world).position());
      if (r.status != planner::PlanStatus::kOk) throw std::invalid_argument(world.source + ": " + r.note);
      render::CoveragePanel panel{name, &p.grid(), p.last_plan(), {}, ""};
      // Held-Karp is exact up to 20 sub-regions; beyond, the order shown is the greedy one.
      if (std::string(name) == "coverage-exact" && !panel.plan.exact_cost && !panel.plan.regions.empty())
        panel.label = "coverage-exact (greedy order: " + std::to_string(panel.plan.regions.size()) + " > 20 regions)";
      const planner::CoverageMetrics& m = panel.plan.metrics;
      all_covered = all_covered && m.covered_cells == m.reachable_cells;
      nlohmann::ordered_json j;
      j["regions"] = panel.plan.regions.size();
      j["order"] = panel.plan.order;
      j["order_cost"] = panel.plan.order_cost;
      j["exact_cost"] = panel.plan.exact_cost ? nlohmann::ordered_json(*panel.plan.exact_cost) : nlohmann::ordered_json();
      j["greedy_cost"] = panel.plan.greedy_cost;
      if (std::string(name) == "coverage")
        j["chnn_settled_on_a_permutation"] = std::to_string(panel.plan.chnn_settled) + " of " + std::to_string(panel.plan.chnn_restarts);
      j["reachable_cells"] = m.reachable_cells;
      j["coverage"] = m.coverage;
      j["repetition"] = m.repetition;
      j["turns"] = m.turns;
      j["dead_ends"] = m.dead_ends;
      j["path_length_m"] = m.length_m;
      std::string driven = "", status = "";
      if (opt->drive) {
        const sim::EpisodeResult e = sim::run_episode(world, p, config);
        for (const auto& s : e.trajectory) panel.driven.push_back(s.truth.position());
        const auto start_cell = p.grid().nearest_free(world.start.position());
        const double dc = start_cell ? driven_coverage(p.grid(), panel.driven, *start_cell) : 0.0;
        char buf[160];
        std::snprintf(buf, sizeof buf, "driven: %s after %.0f s, %.1f %% of cells passed, %d collisions", e.status.c_str(),
                      e.time_s, 100 * dc, e.collisions);
        panel.extra = buf;
        j["driven"] = {{"status", e.status}, {"time_s", e.time_s}, {"driven_coverage", dc}, {"collisions", e.collisions},
                       {"driven_length_m", e.driven_length_m}};
        std::snprintf(buf, sizeof buf, "%.1f", 100 * dc);
        driven = buf;
        status = e.status;
        all_covered = all_covered && e.docked;
      }
      summary["methods"][name] = j;
      char f[6][32];
      std::snprintf(f[0], 32, "%.2f", 100 * m.coverage);
      std::snprintf(f[1], 32, "%.2f", 100 * m.repetition);
      std::snprintf(f[2], 32, "%.1f", m.length_m);
      std::snprintf(f[3], 32, "%.2f", panel.plan.order_cost);
      std::snprintf(f[4], 32, "%.2f", panel.plan.exact_cost ? *panel.plan.exact_cost : 0.0);
      report.rows.push_back({name, std::to_string(panel.plan.regions.size()), f[0], f[1], std::to_string(m.turns),
                             std::to_string(m.dead_ends), f[2], f[3], panel.plan.exact_cost ? f[4] : "-", driven, status});
      std::cout << name << ": " << r.note << (panel.extra.empty() ? "" : "; " + panel.extra) << "\n";
      panels.push_back(std::move(panel));
    }
    const std::string title = world.name + ": full coverage, sub-regions ordered by CHNN, exactly and greedily, and cell by cell";
    render::write_png(render::draw_coverage(world, panels, title), out_dir + "/coverage.png");
    util::write_file_atomically(out_dir + "/coverage.json", summary.dump(2) + "\n");
    report.title = title;
    report.command = command_line(cmd);
    report.figures = {{"coverage.png", "Cells by visits (green once, orange twice, red more), sub-regions numbered in visiting order"}};
    report.files = {"coverage.json"};
    report.notes = "Repetition = visits beyond the first / reachable cells; order cost = sum of D_ij = 0.8 cells + 0.2 turns between "
                   "consecutive sub-regions (the document's weights).";
    render::write_report(report, out_dir + "/report.html");
    staged.commit();
    return all_covered ? kExitOk : kExitFailed;
  };
}

}  // namespace plantsim::app
