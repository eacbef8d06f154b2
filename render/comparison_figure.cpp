// Grid of panels, at most three a row.
#include "render/comparison_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/layers.h"
#include "render/palette.h"
#include "render/run_figure.h"

namespace plantsim::render {

Image draw_comparison(const worlds::World& world, const std::vector<ComparisonPanel>& panels, const std::string& title,
                      int width_px, int panel_height_px) {
  const PanelGrid grid = panel_grid(panels.size(), 3, width_px, panel_height_px);
  Figure fig(width_px, grid.height_px());
  fig.text(title, 20, 32, 20, palette::kAxis, Anchor::kLeft, true);
  const double cell_w = grid.panel_width_px;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const ComparisonPanel& p = panels[i];
    const double x0 = grid.corner(i).x, y0 = grid.corner(i).y;
    const PixelBox box{x0 + 60, y0 + 62, x0 + cell_w - 20, y0 + panel_height_px - 45};
    const PixelTransform t = fig.world_panel(world.floor, box);
    GlCanvas& c = fig.canvas();
    draw_floor(c, world);
    draw_obstacles(c, world);
    if (!p.graph_edges.empty()) draw_graph(c, p.graph_edges);
    if (!p.run.explored.empty()) c.polyline(p.run.explored, 5.0, palette::kExplored);
    draw_plan(c, p.run.plan);
    if (p.drove) {
      draw_target(c, world, p.run.trajectory);
      draw_wall_following(c, p.run.trajectory);
      draw_trajectory_by_speed(c, p.run.trajectory, world.robot.max_speed_mps);
      if (!p.run.trajectory.empty()) draw_footprint(c, world.robot, p.run.trajectory.back().truth, palette::kRobot);
    }
    draw_start(c, world);
    draw_charger(c, world);
    fig.world_axes(world.floor, t);
    char line1[256], line2[256];
    if (p.run.travel == "path")
      std::snprintf(line1, sizeof line1, "%s: path %.2f m, plan %.2f ms", p.label.c_str(), p.run.path_length_m,
                    p.run.plan_stats.build_ms + p.run.plan_stats.query_ms);
    else  // no plan of its own: the drawn plan is the reference
      std::snprintf(line1, sizeof line1, "%s: driven %.2f m (reference plan %.2f m)", p.label.c_str(),
                    p.run.driven_length_m, p.run.path_length_m);
    std::snprintf(line2, sizeof line2, "build %.2f + query %.2f ms, graph %lld vertices, %lld edges", p.run.plan_stats.build_ms,
                  p.run.plan_stats.query_ms, static_cast<long long>(p.run.plan_stats.vertices),
                  static_cast<long long>(p.run.plan_stats.edges));
    fig.text(line1, x0 + 60, y0 + 20, 15, palette::kAxis, Anchor::kLeft, true);
    fig.text(line2, x0 + 60, y0 + 38, 12, palette::kAxis);
    fig.text(p.drove ? result_line(p.run) : p.run.status, x0 + 60, y0 + 54, 12, palette::kAxis);
  }
  return fig.finish();
}

}  // namespace plantsim::render
