// Grid of panels (one row up to three, two by two for four, then rows of three) under a legend
// of what the panels draw and the speed scale.
#include "render/comparison_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/layers.h"
#include "render/method_marks.h"
#include "render/palette.h"
#include "render/run_figure.h"
#include "util/c_number.h"

namespace plantsim::render {

using planner::PlanStats;

std::string what_differs(const ComparisonPanel& a, const ComparisonPanel& b) {
  const PlanStats &x = a.run.plan_stats, &y = b.run.plan_stats;
  // Only two different graph planners: two ways of travelling on one plan share its numbers.
  if (x.vertices <= 0 || y.vertices <= 0 || a.run.plan.empty() || b.run.plan.empty() ||
      a.run.planner == b.run.planner || searches_a_mesh(a.run.planner) ||
      searches_a_mesh(b.run.planner))  // cells and portals are no vertices and edges
    return "";
  const double la = a.run.path_length_m, lb = b.run.path_length_m;
  const double ta = x.build_ms + x.query_ms, tb = y.build_ms + y.query_ms;
  char line[512];
  util::c_snprintf(
      line, sizeof line,
      "%s vs %s: path %.2f vs %.2f m (%s); vertices %lld vs %lld; edges evaluated %lld vs %lld; "
      "segment tests %lld vs %lld; plan time %.2f vs %.2f ms",
      a.label.c_str(), b.label.c_str(), la, lb,
      std::fabs(la - lb) < 5e-3 ? "the same length" : "lengths differ",
      static_cast<long long>(x.vertices), static_cast<long long>(y.vertices),
      static_cast<long long>(x.edges), static_cast<long long>(y.edges),
      static_cast<long long>(x.segment_tests), static_cast<long long>(y.segment_tests), ta, tb);
  return line;
}

namespace {

/// One panel's world layers; true when it drew a driven path.
bool draw_panel_layers(Figure& fig, const PixelTransform& t, const worlds::World& world,
                       const ComparisonPanel& p, UniqueLegend& listed) {
  bool drove_any = false;
  GlCanvas& c = fig.canvas();
  draw_floor(c, world);
  const MarginShape shape = margin_shape(p.run.planner.empty() ? p.label : p.run.planner);
  const bool obstacles = draw_obstacles(c, world, shape);
  listed(obstacles, palette::kObstacle, "obstacle");
  listed(obstacles && world.planning_inflation_m() > 0, palette::kInflation,
         shape == MarginShape::kRound ? "rounded margin" : "planning margin");
  listed(draw_graph(c, p.graph_edges), palette::kGraph,
         searches_a_mesh(p.run.planner) ? "mesh portals" : "graph");
  for (const LegendEntry& e : draw_walks_before_answer(c, p.run)) listed(true, e.colour, e.label);
  if (p.drove) {
    listed(draw_moving_tracks(c, p.run.moving_tracks), palette::kMoving,
           moving_tracks_label(p.run.moving_tracks));
    listed(draw_target(c, world, p.run.trajectory), palette::kTarget, "target");
    listed(draw_wall_following(c, p.run.trajectory), palette::kWallFollow, "wall following");
    const bool drove = draw_trajectory_by_speed(c, p.run.trajectory, world.robot.max_speed_mps);
    listed(drove, speed_swatch(p.run.trajectory, world.robot.max_speed_mps), "driven (speed)");
    drove_any = drove_any || drove;
    // Where collisions began: the cause of a failure is part of the comparison.
    std::vector<episode::EpisodeResult::Event> collisions;
    for (const auto& e : p.run.events)
      if (e.kind == episode::EpisodeResult::Event::Kind::kCollision) collisions.push_back(e);
    draw_events(c, collisions);
    listed(!collisions.empty(), palette::kCollisionMark, "collision");
    if (!p.run.trajectory.empty())
      draw_footprint(c, world.robot, p.run.trajectory.back().truth, palette::kRobot, 2.0);
    listed(!p.run.trajectory.empty(), palette::kRobot, "robot at the end");
  }
  listed(draw_plan(c, p.run.plan, palette::kPlan), palette::kPlan,
         p.run.travel == "path" ? "plan" : "plan (reference)");
  draw_start(c, world);
  draw_charger(c, world);
  for (const LegendEntry& e : draw_plan_marks(fig, t, p.run.plan_trace.marks))
    listed(true, e.colour, e.label);
  return drove_any;
}

/// What the planner searched, in its own terms.
std::string structure_text(const ComparisonPanel& p) {
  const PlanStats& st = p.run.plan_stats;
  std::string structure;
  if (searches_a_mesh(p.run.planner))
    structure = "mesh " + std::to_string(st.vertices) + " cells, " + std::to_string(st.edges) +
                " portals, " + std::to_string(st.expanded) + " intervals expanded";
  else if (p.run.planner.rfind("grid", 0) == 0)
    structure =
        std::to_string(st.vertices) + " free cells, " + std::to_string(st.expanded) + " expanded";
  else if (st.vertices > 0 && !p.graph_edges.empty())
    structure = "graph " + std::to_string(st.vertices) + " vertices, " +
                std::to_string(p.graph_edges.size()) + " edges drawn, " + std::to_string(st.edges) +
                " evaluated by the search";
  else if (st.vertices > 0)
    structure = "graph " + std::to_string(st.vertices) + " vertices, " + std::to_string(st.edges) +
                " edges evaluated";
  else
    structure = "no graph (works on the obstacles directly)";
  if (st.segment_tests > 0) structure += ", " + std::to_string(st.segment_tests) + " segment tests";
  return structure;
}

/// The panel's three lines over it: length and time, the search's structure, the result.
void draw_panel_text(Figure& fig, const ComparisonPanel& p, double x0, double y0, double cell_w) {
  char line1[256], line2[256];
  if (p.run.travel == "path")
    util::c_snprintf(line1, sizeof line1, "%s: path %.2f m, plan %.2f ms", p.label.c_str(),
                     p.run.path_length_m, p.run.plan_stats.build_ms + p.run.plan_stats.query_ms);
  else  // no plan of its own: the drawn plan is the reference
    util::c_snprintf(line1, sizeof line1, "%s: driven %.2f m (reference plan %.2f m)",
                     p.label.c_str(), p.run.driven_length_m, p.run.path_length_m);
  const PlanStats& st = p.run.plan_stats;
  const std::string structure = structure_text(p);
  util::c_snprintf(line2, sizeof line2, "build %.2f + query %.2f ms, %s", st.build_ms, st.query_ms,
                   structure.c_str());
  fig.text_fitted(line1, x0 + 60, y0 + 20, 15, palette::kAxis, cell_w - 80, true);
  fig.text_fitted(line2, x0 + 60, y0 + 38, 12, palette::kAxis, cell_w - 80);
  fig.text_fitted(p.drove ? result_line(p.run) : episode::status_name(p.run), x0 + 60, y0 + 54, 12,
                  palette::kAxis, cell_w - 80);
}

}  // namespace

Image draw_comparison(const worlds::World& world, const std::vector<ComparisonPanel>& panels,
                      const std::string& title, int width_px, int panel_height_px,
                      FigureLayout* layout_out) {
  const int columns = panels.size() == 4 ? 2 : 3;
  PanelGrid grid = panel_grid(panels.size(), columns, width_px, panel_height_px);
  // Two graph planners side by side (the document's Fig. 5 and Fig. 6): say under the title
  // what differs between them and what does not.
  const std::string differences = panels.size() == 2 ? what_differs(panels[0], panels[1]) : "";
  const double legend_y = differences.empty() ? 62 : 80;
  grid.top_px = differences.empty() ? 110 : 126;
  Figure fig(width_px, grid.height_px());
  fig.text_fitted(title, 20, 32, 20, palette::kAxis, width_px - 40.0, true);
  if (!differences.empty())
    fig.text_fitted(differences, 20, 54, 13, palette::kAxis, width_px - 40.0);
  const double cell_w = grid.panel_width_px;
  UniqueLegend listed;
  bool drove_any = false;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const ComparisonPanel& p = panels[i];
    const double x0 = grid.corner(i).x, y0 = grid.corner(i).y;
    const PixelBox box{x0 + 60, y0 + 80, x0 + cell_w - 20, y0 + panel_height_px - 45};
    const PixelTransform t = fig.world_panel(world.floor, box);
    fig.clip_to_world(world.floor, t);
    drove_any = draw_panel_layers(fig, t, world, p, listed) || drove_any;
    fig.world_axes(world.floor, t);
    draw_panel_text(fig, p, x0, y0, cell_w);
  }
  listed(true, palette::kStart, "start");
  listed(true, palette::kCharger, "charger");
  const std::vector<LegendEntry>& legend = listed.entries;
  // One row while it fits beside the speed scale, else two (the panels start below both).
  const double legend_width = width_px - 40.0 - (drove_any ? 270.0 : 0.0);
  const int fitting = std::max(1, static_cast<int>(legend_width / 150.0));
  const int legend_rows = legend.size() > static_cast<std::size_t>(fitting) ? 2 : 1;
  const int legend_columns = static_cast<int>((legend.size() + legend_rows - 1) / legend_rows);
  fig.legend(20, legend_y, legend, legend_columns,
             std::min(150.0, legend_width / std::max(1, legend_columns)));
  if (drove_any)
    fig.colour_bar({width_px - 260.0, 78, width_px - 30.0, 88}, 0.0, world.robot.max_speed_mps,
                   "speed (m/s)");
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

}  // namespace plantsim::render
