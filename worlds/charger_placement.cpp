// Docking-heading choice for point chargers.
#include "worlds/charger_placement.h"

#include <cmath>
#include <vector>

#include "geometry/predicates.h"

namespace plantsim::worlds {
bool docking_area_clear(const World& world) {
  std::vector<Rect> blockers = world.obstacles;
  for (const Rect& w : geom::surrounding_walls(world.floor, 1.0)) blockers.push_back(w);
  const Rect body = charger_body(world).bounding_box();
  const Pose2 staging = staging_pose(world);
  const double r = world.robot.radius_m;
  const double clearance = world.planning_inflation_m();
  for (const Rect& b : blockers) {
    if (geom::rects_overlap_open(body, b)) return false;
    if (geom::segment_enters_open_rect(staging.position(), world.charger.position(), b.inflated(r)))
      return false;
    if (!geom::in_closed_rect(world.floor, staging.position()) ||
        geom::in_open_rect(b.inflated(clearance), staging.position()))
      return false;
  }
  return true;
}

std::optional<double> choose_docking_heading(const World& world, Vec2 dock_point) {
  const Vec2 from_start = dock_point - world.start.position();
  std::optional<double> best;
  double best_alignment = -2.0;
  for (int k = 0; k < 8; ++k) {
    const double yaw = geom::wrap_angle(k * M_PI / 4.0);
    World trial = world;
    trial.charger = {dock_point.x, dock_point.y, yaw};
    if (!docking_area_clear(trial)) continue;
    const double length = geom::norm(from_start);  // 0 when the start is at the dock point
    const double alignment =
        length > 0 ? geom::dot(geom::unit_from_angle(yaw), from_start) / length : 0.0;
    if (alignment > best_alignment) {
      best_alignment = alignment;
      best = yaw;
    }
  }
  return best;
}

}  // namespace plantsim::worlds
