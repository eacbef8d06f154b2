// Two panels a row.
#include "render/coverage_figure.h"

#include <algorithm>
#include <cstdio>

#include "render/layers.h"
#include "render/palette.h"

namespace plantsim::render {
namespace {

constexpr Rgb kCoveredOnce{150, 215, 140};
constexpr Rgb kCoveredTwice{250, 190, 90};
constexpr Rgb kCoveredMore{230, 90, 60};
constexpr Rgb kRegionOutline{40, 70, 160};

}  // namespace

Image draw_coverage(const worlds::World& world, const std::vector<CoveragePanel>& panels, const std::string& title,
                    int width_px, int panel_height_px) {
  const PanelGrid grid = panel_grid(panels.size(), 2, width_px, panel_height_px);
  Figure fig(width_px, grid.height_px());
  fig.text(title, 20, 32, 20, palette::kAxis, Anchor::kLeft, true);
  const double cell_w = grid.panel_width_px;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const CoveragePanel& p = panels[i];
    const planner::CoverageGrid& g = *p.grid;
    const double x0 = grid.corner(i).x, y0 = grid.corner(i).y;
    const PixelBox box{x0 + 60, y0 + 80, x0 + cell_w - 20, y0 + panel_height_px - 45};
    const PixelTransform t = fig.world_panel(world.floor, box);
    GlCanvas& c = fig.canvas();
    draw_floor(c, world);
    std::vector<int> visits(static_cast<std::size_t>(g.columns()) * g.rows(), 0);
    for (const planner::Cell& cell : p.plan.cells) ++visits[g.index(cell)];
    for (int r = 0; r < g.rows(); ++r)
      for (int col = 0; col < g.columns(); ++col) {
        const planner::Cell cell{col, r};
        const int v = visits[g.index(cell)];
        if (!g.free(cell)) c.fill_rect(g.cell_rect(cell), palette::kFootprint, 0.6f);
        else if (v == 1) c.fill_rect(g.cell_rect(cell), kCoveredOnce);
        else if (v == 2) c.fill_rect(g.cell_rect(cell), kCoveredTwice);
        else if (v > 2) c.fill_rect(g.cell_rect(cell), kCoveredMore);
      }
    draw_obstacles(c, world);
    for (const planner::CellRect& r : p.plan.regions) {
      const geom::Rect a = g.cell_rect({r.column, r.row}), b = g.cell_rect({r.column + r.width - 1, r.row + r.height - 1});
      c.polyline({{a.xmin, a.ymin}, {b.xmax, a.ymin}, {b.xmax, b.ymax}, {a.xmin, b.ymax}, {a.xmin, a.ymin}}, 2.0,
                 kRegionOutline);
    }
    std::vector<Vec2> path;
    for (const planner::Cell& cell : p.plan.cells) path.push_back(g.centre(cell));
    c.polyline(path, 1.5, palette::kPlan);
    if (!p.driven.empty()) c.polyline(p.driven, 1.2, palette::kTrajectory);
    draw_start(c, world);
    draw_charger(c, world);
    fig.world_axes(world.floor, t);
    // The visiting order, numbered at each sub-region's centre.
    for (std::size_t k = 0; k < p.plan.order.size(); ++k) {
      const planner::CellRect& r = p.plan.regions[p.plan.order[k]];
      const Vec2 centre = 0.5 * (g.centre({r.column, r.row}) + g.centre({r.column + r.width - 1, r.row + r.height - 1}));
      const Vec2 px = t.to_pixel(centre);
      fig.text(std::to_string(k + 1), px.x, px.y + 6, 15, kRegionOutline, Anchor::kCenter, true);
    }
    const planner::CoverageMetrics& m = p.plan.metrics;
    char line1[256], line2[256];
    std::snprintf(line1, sizeof line1, "%s: coverage %.1f %%, repetition %.2f %%, %d turns, %d dead ends, %.0f m",
                  p.label.c_str(), 100 * m.coverage, 100 * m.repetition, m.turns, m.dead_ends, m.length_m);
    if (p.plan.regions.empty())
      std::snprintf(line2, sizeof line2, "cell by cell (no sub-regions); %d reachable cells", m.reachable_cells);
    else if (p.plan.exact_cost)
      std::snprintf(line2, sizeof line2, "%d sub-regions, order cost %.2f (exact %.2f, greedy %.2f)",
                    static_cast<int>(p.plan.regions.size()), p.plan.order_cost, *p.plan.exact_cost, p.plan.greedy_cost);
    else
      std::snprintf(line2, sizeof line2, "%d sub-regions, order cost %.2f (greedy %.2f; too many for the exact order)",
                    static_cast<int>(p.plan.regions.size()), p.plan.order_cost, p.plan.greedy_cost);
    fig.text(line1, x0 + 60, y0 + 20, 15, palette::kAxis, Anchor::kLeft, true);
    fig.text(line2, x0 + 60, y0 + 38, 12, palette::kAxis);
    if (!p.extra.empty()) fig.text(p.extra, x0 + 60, y0 + 54, 12, palette::kAxis);
  }
  return fig.finish();
}

}  // namespace plantsim::render
