// `plantsim coverage WORLD`: seed 004's full-coverage methods side by side on one work area
// (sub-regions ordered by the document's CHNN, by annealed Potts neurons, proven optimally and
// greedily, and cell-by-cell coverage), with the document's metrics beside its own numbers;
// --drive also sweeps and docks in the simulation and measures the cells the robot's centre
// actually passed through. Exit 1 when a method has no plan or leaves a reachable cell
// uncovered (or, with --drive, does not dock).
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/coverage_runs.h"
#include "episode/episode_config_json.h"
#include "episode/run_episode.h"
#include "planner/coverage/coverage_params_json.h"
#include "render/coverage_figure.h"
#include "render/png_io.h"
#include "render/report.h"
#include "util/atomic_file.h"
#include "util/c_number.h"
#include "worlds/known_keys.h"
#include "worlds/world_loader.h"

namespace plantsim::app {
namespace {

// Reachable cells the robot's centre passed through.
double driven_coverage(const planner::CoverageGrid& g, const std::vector<geom::Vec2>& trajectory,
                       planner::Cell start) {
  const std::vector<bool> reach = g.reachable(start);
  std::vector<bool> seen(reach.size(), false);
  for (const geom::Vec2& p : trajectory)
    if (const auto c = g.cell_at(p)) seen[g.index(*c)] = true;
  int reachable = 0, covered = 0;
  for (std::size_t i = 0; i < reach.size(); ++i)
    reachable += reach[i], covered += reach[i] && seen[i];
  return reachable ? static_cast<double>(covered) / reachable : 0.0;
}

std::string percent(double share) {
  char s[32];
  util::c_snprintf(s, sizeof s, "%.2f %%", 100 * share);
  return s;
}

struct CoverageOptions {
  std::string world, out, config, params;
  double cell_m = 0;
  bool drive = false;
};

/// One method's plan driven in the simulation: its panel's driven path and note, its JSON entry
/// and table cells; false unless it docked.
bool drive_coverage(const worlds::World& world, const episode::EpisodeConfig& config,
                    CoverageRun& run, render::CoveragePanel& panel, nlohmann::ordered_json& j,
                    std::string& driven, std::string& status) {
  const episode::EpisodeResult e = episode::run_episode(world, *run.planner, config);
  for (const auto& s : e.trajectory) panel.driven.push_back(s.truth.position());
  const auto start_cell = run.planner->grid().nearest_free(world.start.position());
  const double dc =
      start_cell ? driven_coverage(run.planner->grid(), panel.driven, *start_cell) : 0.0;
  char buf[160];
  util::c_snprintf(buf, sizeof buf,
                   "driven: %s after %.0f s, %.1f %% of cells passed, %d collisions",
                   episode::status_name(e).c_str(), e.time_s, 100 * dc, e.collisions);
  panel.extra = buf;
  j["driven"] = {{"status", episode::status_name(e)},
                 {"time_s", e.time_s},
                 {"driven_coverage", dc},
                 {"collisions", e.collisions},
                 {"driven_length_m", e.driven_length_m}};
  util::c_snprintf(buf, sizeof buf, "%.1f", 100 * dc);
  driven = buf;
  status = episode::status_name(e);
  return e.docked;
}

/// Every method's panel, summary entry and table row; false when one leaves a reachable cell
/// uncovered (or, driven, does not dock).
bool cover_all(const worlds::World& world, const CoverageOptions& opt,
               const episode::EpisodeConfig& config, std::vector<CoverageRun>& runs,
               std::vector<render::CoveragePanel>& panels, nlohmann::ordered_json& summary,
               render::Report& report) {
  bool all_covered = true;
  for (CoverageRun& run : runs) {
    render::CoveragePanel panel{run.method, &run.planner->grid(), run.planner->last_plan(), {}, ""};
    const planner::CoverageMetrics& m = panel.plan.metrics;
    all_covered = all_covered && run.planned() && m.covered_cells == m.reachable_cells;
    nlohmann::ordered_json j = coverage_plan_json(run);
    std::string driven, status;
    if (opt.drive && run.planned())
      all_covered = drive_coverage(world, config, run, panel, j, driven, status) && all_covered;
    summary["methods"][run.method] = j;
    char f[3][32];
    util::c_snprintf(f[0], 32, "%.2f", 100 * m.coverage);
    util::c_snprintf(f[1], 32, "%.2f", 100 * m.repetition);
    util::c_snprintf(f[2], 32, "%.1f", m.length_m);
    report.rows.push_back({run.method, std::to_string(panel.plan.regions.size()),
                           run.planned() ? f[0] : "-", run.planned() ? f[1] : "-",
                           std::to_string(m.turns), std::to_string(m.dead_ends), f[2],
                           render::describe_order(panel.plan), driven, status});
    std::cout << run.method << ": " << run.result.note
              << (panel.extra.empty() ? "" : "; " + panel.extra) << "\n";
    panels.push_back(std::move(panel));
  }
  return all_covered;
}

/// The document's two numbers beside ours: its map is not published, so this is the same
/// measure on this work area, not the same experiment.
std::string document_subtitle(const std::vector<CoverageRun>& runs) {
  const planner::CoveragePlan& chnn = runs[0].planner->last_plan();
  const planner::CoveragePlan& cells = runs.back().planner->last_plan();
  return "Repetition, document (its own 40 x 20 m map) vs here: CHNN " +
         percent(kDocumentRepetitionChnn) + " vs " +
         (chnn.ok ? percent(chnn.metrics.repetition) : std::string("no plan")) + "; cell by cell " +
         percent(kDocumentRepetitionCells) + " vs " + percent(cells.metrics.repetition);
}

}  // namespace

std::function<int()> add_coverage_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("coverage", "Seed 004: full-coverage methods compared on one work area");
  auto opt = std::make_shared<CoverageOptions>();
  cmd->add_option("world", opt->world, "World file")->required();
  cmd->add_option("--out", opt->out, "Output folder (default results/<world>_coverage)");
  cmd->add_option("--params", opt->params,
                  "Coverage parameters (JSON; defaults: configs/coverage_params.json)");
  cmd->add_option("--cell", opt->cell_m, "Cell size (m), over the parameters' cell_m")
      ->check(CLI::Range(0.2, 100.0));
  cmd->add_option("--config", opt->config, "Episode parameters for --drive (JSON)");
  cmd->add_flag("--drive", opt->drive, "Also sweep and dock in the simulation");
  return [opt, cmd]() {
    const worlds::World world = worlds::load_world(opt->world);
    episode::EpisodeConfig config;
    if (!opt->config.empty()) config = episode::load_episode_config(opt->config);
    planner::CoverageParams params = opt->params.empty()
                                         ? planner::CoverageParams{}
                                         : planner::load_coverage_params(opt->params);
    if (opt->cell_m > 0) params.cell_m = opt->cell_m;
    util::StagedFolder staged(
        opt->out.empty() ? "results/" + worlds::file_name_component(world.name) + "_coverage"
                         : opt->out,
        {"coverage.png", "coverage.json", "report.html"});
    const std::string& out_dir = staged.path();
    std::vector<CoverageRun> runs = plan_coverage_methods(world, params);
    std::vector<render::CoveragePanel> panels;
    nlohmann::ordered_json summary;
    summary["world"] = world.name;
    summary["command"] = command_line(cmd);
    summary["parameters"] = nlohmann::ordered_json::parse(planner::coverage_params_json(params));
    render::Report report;
    report.headers = {"method",
                      "regions",
                      "coverage (%)",
                      "repetition (%)",
                      "turns",
                      "dead ends",
                      "path (m)",
                      "how the order was found",
                      "driven coverage (%)",
                      "episode"};
    const bool all_covered = cover_all(world, *opt, config, runs, panels, summary, report);
    summary["document"] = {{"repetition_chnn", kDocumentRepetitionChnn},
                           {"repetition_cells", kDocumentRepetitionCells}};
    const std::string subtitle = document_subtitle(runs);
    const std::string title =
        world.name +
        ": full coverage by sub-regions (CHNN, Potts, proven optimum, greedy) and cell by cell";
    render::write_png(render::draw_coverage(world, panels, title, subtitle),
                      out_dir + "/coverage.png");
    util::write_file_atomically(out_dir + "/coverage.json", summary.dump(2) + "\n");
    report.title = title;
    report.command = command_line(cmd);
    report.figures = {{"coverage.png",
                       "Cells by visits (blue once, orange twice, purple more), sub-regions "
                       "numbered in visiting order, green dots where each sweep starts. " +
                           subtitle}};
    report.files = {"coverage.json"};
    report.notes =
        "Repetition = visits beyond the first / reachable cells, the way from the start to the "
        "charger's cell included; order cost = sum of D = w1 cells + w2 turns from each sweep's "
        "end to the next sweep's start and through it (w1 = 0.8, w2 = 0.2, the document's). "
        "docs/seeds.md says what is the document's and what is not.";
    render::write_report(report, out_dir + "/report.html");
    staged.commit();
    return all_covered ? kExitOk : kExitFailed;
  };
}

}  // namespace plantsim::app
