// Two panels a row under a legend of what they draw (visit counts in colour-blind-safe tints,
// the coverage path in black so that it shows on any tint).
#include "render/coverage_figure.h"

#include <algorithm>
#include <cstdio>

#include "render/layers.h"
#include "render/palette.h"
#include "util/c_number.h"

namespace plantsim::render {
namespace {

constexpr Rgb kCoveredOnce{190, 225, 245};  // tints of Okabe-Ito sky blue, orange, reddish purple
constexpr Rgb kCoveredTwice{245, 205, 120};
constexpr Rgb kCoveredMore{215, 140, 185};
constexpr Rgb kBlocked{180, 180, 185};
constexpr Rgb kRegionOutline = palette::kOkabeBlue;
constexpr Rgb kCoveragePath{0, 0, 0};
constexpr Rgb kSweepStart = palette::kOkabeYellow;  // vermillion is the driven path's

}  // namespace

std::string describe_order(const planner::CoveragePlan& p) {
  char line[256];
  if (!p.ok) return p.failure;
  if (p.regions.empty()) {
    util::c_snprintf(line, sizeof line, "cell by cell (no sub-regions); %d reachable cells",
                     p.metrics.reachable_cells);
    return line;
  }
  util::c_snprintf(line, sizeof line, "%d sub-regions, order cost %.2f (greedy %.2f)",
                   static_cast<int>(p.regions.size()), p.order_cost, p.greedy_cost);
  std::string s = line;
  if (p.network_restarts > 0) {
    util::c_snprintf(line, sizeof line, "; valid order in %d of %d restarts", p.network_valid,
                     p.network_restarts);
    s += line;
  }
  if (p.exact) {
    if (!p.exact->searched)
      util::c_snprintf(line, sizeof line, "; NOT searched: the search handles at most 63 regions");
    else if (p.exact->proven)
      util::c_snprintf(line, sizeof line, "; proven optimal in %.1f s", p.exact->seconds);
    else
      util::c_snprintf(line, sizeof line, "; NOT proven optimal in %.0f s (bound %.2f)",
                       p.exact->seconds, p.exact->lower_bound);
    s += line;
  }
  return s;
}

namespace {

/// The grid's cells by visits (blocked, once, twice, more).
void draw_cells(GlCanvas& c, const planner::CoverageGrid& g, const CoveragePanel& p,
                UniqueLegend& listed) {
  std::vector<int> visits(static_cast<std::size_t>(g.columns()) * g.rows(), 0);
  for (const planner::Cell& cell : p.plan.cells) ++visits[g.index(cell)];
  for (int r = 0; r < g.rows(); ++r)
    for (int col = 0; col < g.columns(); ++col) {
      const planner::Cell cell{col, r};
      const int v = visits[g.index(cell)];
      if (!g.free(cell))
        c.fill_rect(g.cell_rect(cell), kBlocked);
      else if (v == 1)
        c.fill_rect(g.cell_rect(cell), kCoveredOnce);
      else if (v == 2)
        c.fill_rect(g.cell_rect(cell), kCoveredTwice);
      else if (v > 2)
        c.fill_rect(g.cell_rect(cell), kCoveredMore);
      listed(!g.free(cell), kBlocked, "blocked cell");
      listed(g.free(cell) && v == 1, kCoveredOnce, "covered once");
      listed(g.free(cell) && v == 2, kCoveredTwice, "covered twice");
      listed(g.free(cell) && v > 2, kCoveredMore, "covered 3+ times");
    }
}

/// The sub-regions' outlines, where each sweep starts, the coverage path and the driven one.
void draw_regions_and_paths(GlCanvas& c, const planner::CoverageGrid& g, const CoveragePanel& p,
                            UniqueLegend& listed) {
  for (const planner::CellRect& r : p.plan.regions) {
    const geom::Rect a = g.cell_rect({r.column, r.row}),
                     b = g.cell_rect({r.column + r.width - 1, r.row + r.height - 1});
    c.polyline(
        {{a.xmin, a.ymin}, {b.xmax, a.ymin}, {b.xmax, b.ymax}, {a.xmin, b.ymax}, {a.xmin, a.ymin}},
        2.0, kRegionOutline);
  }
  listed(!p.plan.regions.empty(), kRegionOutline, "sub-region, order");
  // Where each sweep starts: its lanes run from there.
  bool sweep_starts = false;
  for (const planner::Cell& first : p.plan.sweep_starts) {
    c.fill_disk(g.centre(first), 0.18 * g.cell_m(), kSweepStart);
    c.ring(g.centre(first), 0.18 * g.cell_m(), 1.0,
           kCoveragePath);  // yellow needs an edge on pale tints
    sweep_starts = true;
  }
  listed(sweep_starts, kSweepStart, "sweep start");
  std::vector<Vec2> path;
  for (const planner::Cell& cell : p.plan.cells) path.push_back(g.centre(cell));
  c.polyline(path, 1.5, kCoveragePath);
  listed(path.size() > 1, kCoveragePath, "coverage path");
  if (!p.driven.empty()) c.polyline(p.driven, 1.5, palette::kPlan);
  listed(p.driven.size() > 1, palette::kPlan, "driven");
}

/// The visiting order, numbered at each sub-region's centre.
void draw_order_numbers(Figure& fig, const PixelTransform& t, const planner::CoverageGrid& g,
                        const CoveragePanel& p) {
  for (std::size_t k = 0; k < p.plan.order.size(); ++k) {
    const planner::CellRect& r = p.plan.regions[p.plan.order[k]];
    const Vec2 centre = 0.5 * (g.centre({r.column, r.row}) +
                               g.centre({r.column + r.width - 1, r.row + r.height - 1}));
    const Vec2 px = t.to_pixel(centre);
    fig.text(std::to_string(k + 1), px.x, px.y + 6, 15, kRegionOutline, Anchor::kCenter, true);
  }
}

void draw_panel_text(Figure& fig, const CoveragePanel& p, double x0, double y0, double cell_w) {
  const planner::CoverageMetrics& m = p.plan.metrics;
  char line1[256];
  if (p.plan.ok)
    util::c_snprintf(line1, sizeof line1,
                     "%s: coverage %.1f %%, repetition %.2f %%, %d turns, %d dead ends, %.0f m",
                     p.label.c_str(), 100 * m.coverage, 100 * m.repetition, m.turns, m.dead_ends,
                     m.length_m);
  else
    util::c_snprintf(line1, sizeof line1, "%s: NO PLAN", p.label.c_str());
  fig.text_fitted(line1, x0 + 60, y0 + 20, 15,
                  p.plan.ok ? palette::kAxis : palette::kOkabeVermillion, cell_w - 80, true);
  fig.text_fitted(describe_order(p.plan), x0 + 60, y0 + 38, 12, palette::kAxis, cell_w - 80);
  if (!p.extra.empty()) fig.text_fitted(p.extra, x0 + 60, y0 + 54, 12, palette::kAxis, cell_w - 80);
}

}  // namespace

Image draw_coverage(const worlds::World& world, const std::vector<CoveragePanel>& panels,
                    const std::string& title, const std::string& subtitle, int width_px,
                    int panel_height_px, FigureLayout* layout_out) {
  PanelGrid grid = panel_grid(panels.size(), 2, width_px, panel_height_px);
  // Room under the title and its subtitle for a legend of up to 12 entries in at most two rows.
  const int legend_columns = std::max(1, std::min(6, (width_px - 40) / 170));
  grid.top_px = 64 + 22 + 2 * 19 + 16;
  Figure fig(width_px, grid.height_px());
  UniqueLegend listed;
  fig.text_fitted(title, 20, 32, 20, palette::kAxis, width_px - 40.0, true);
  fig.text_fitted(subtitle, 20, 58, 14, palette::kAxis, width_px - 40.0);
  const double cell_w = grid.panel_width_px;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const CoveragePanel& p = panels[i];
    const planner::CoverageGrid& g = *p.grid;
    const double x0 = grid.corner(i).x, y0 = grid.corner(i).y;
    const PixelBox box{x0 + 60, y0 + 80, x0 + cell_w - 20, y0 + panel_height_px - 45};
    const PixelTransform t = fig.world_panel(world.floor, box);
    GlCanvas& c = fig.canvas();
    draw_floor(c, world);
    draw_cells(c, g, p, listed);
    const bool obstacles = draw_obstacles(c, world);
    listed(obstacles, palette::kObstacle, "obstacle");
    listed(obstacles && world.planning_inflation_m() > 0, palette::kInflation, "margin");
    draw_regions_and_paths(c, g, p, listed);
    draw_start(c, world);
    draw_charger(c, world);
    fig.world_axes(world.floor, t);
    draw_order_numbers(fig, t, g, p);
    draw_panel_text(fig, p, x0, y0, cell_w);
  }
  listed(true, palette::kStart, "start");
  listed(true, palette::kCharger, "charger");
  fig.legend(20, 86, listed.entries, legend_columns, 170);
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

}  // namespace plantsim::render
