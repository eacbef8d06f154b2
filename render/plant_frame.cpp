// One frame of the plant (see the header): the animation's layers, in the run figure's order.
#include "render/plant_frame.h"

#include "render/figure.h"
#include "render/layers.h"
#include "render/palette.h"
#include "util/c_number.h"

namespace plantsim::render {

Image plant_frame(const worlds::World& world, const PlantInstant& at, int width_px, int height_px) {
  Figure fig(width_px, height_px);
  const PixelTransform t =
      fig.world_panel(world.floor, {50, 40, width_px - 170.0, height_px - 40.0});
  GlCanvas& c = fig.canvas();
  std::vector<LegendEntry> legend;
  draw_floor(c, world);
  if (draw_obstacles(c, world)) {
    legend.push_back({palette::kObstacle, "obstacle"});
    if (world.planning_inflation_m() > 0) legend.push_back({palette::kInflation, "margin"});
  }
  if (draw_unmapped(c, world)) legend.push_back({palette::kUnmapped, "not on map"});
  if (draw_moving(c, world, at.t_s, at.moving)) legend.push_back({palette::kMoving, "moving"});
  static const std::vector<episode::EpisodeResult::Carry> kNoCarries;
  if (at.trajectory && draw_trajectory_by_speed(c, *at.trajectory, world.robot.max_speed_mps,
                                                at.driven, at.carries ? *at.carries : kNoCarries))
    legend.push_back({speed_swatch(*at.trajectory, world.robot.max_speed_mps), "driven (speed)"});
  if (at.carries) {  // the kidnaps so far, dashed from where it was lifted to where it was set down
    std::vector<episode::EpisodeResult::Carry> so_far;
    for (const auto& carry : *at.carries)
      if (carry.t_s <= at.t_s) so_far.push_back(carry);
    if (draw_carries(c, so_far)) legend.push_back({palette::kCarry, "kidnap", Swatch::kDashed});
  }
  if (draw_plan(c, at.plan, palette::kPlan)) legend.push_back({palette::kPlan, "plan"});
  if (at.scan) {  // legend entries for what is drawn, as the run figure's
    const auto [explained, unexplained] = draw_scan(c, *at.scan);
    if (explained) legend.push_back({palette::kScan, "last scan", Swatch::kDot});
    if (unexplained) legend.push_back({palette::kScanOffMap, "scan off map", Swatch::kDot});
  }
  if (draw_layer(c, at.layer))
    legend.push_back({palette::kLayer, "sensed layer", Swatch::kOutline});
  if (draw_tracked(c, at.tracked))
    legend.push_back({palette::kTracked, "tracked", Swatch::kOutline});
  draw_start(c, world);
  draw_charger(c, world);
  draw_mapped_charger(c, world);
  draw_footprint(c, world.robot, at.robot, palette::kRobot, 2.0);
  legend.push_back({palette::kRobot, "robot", Swatch::kRing});
  legend.push_back({palette::kStart, "start", Swatch::kDot});
  legend.push_back({palette::kCharger, "charger"});
  fig.legend(width_px - 150.0, 60, legend);
  fig.world_axes(world.floor, t);
  char title[160];
  util::c_snprintf(title, sizeof title, "%s  t = %.1f s  %s", world.name.c_str(), at.t_s,
                   at.phase.c_str());
  fig.text(title, 50, 26, 16, palette::kAxis, Anchor::kLeft, true);
  return fig.finish();
}

}  // namespace plantsim::render
