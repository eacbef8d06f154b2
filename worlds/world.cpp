// Derived charger geometry of a World.
#include "worlds/world.h"

#include <algorithm>
#include <cmath>

namespace plantsim::worlds {

Vec2 MovingObstacle::position_at(double t_s) const {
  if (waypoints.size() < 2 || speed_mps <= 0 || t_s <= start_time_s) return waypoints.front();
  double total = 0;
  for (std::size_t i = 1; i < waypoints.size(); ++i)
    total += geom::distance(waypoints[i - 1], waypoints[i]);
  if (total <= 0) return waypoints.front();
  double s = (t_s - start_time_s) * speed_mps;
  if (loop) {
    s = std::fmod(s, 2 * total);
    if (s > total) s = 2 * total - s;  // on the way back
  } else if (s >= total) {
    return waypoints.back();
  }
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    const double seg = geom::distance(waypoints[i - 1], waypoints[i]);
    if (s <= seg && seg > 0)
      return waypoints[i - 1] + (s / seg) * (waypoints[i] - waypoints[i - 1]);
    s -= seg;
  }
  return waypoints.back();
}

Rect MovingObstacle::box_at(double t_s) const {
  const Vec2 c = position_at(t_s);
  return {c.x - 0.5 * width_m, c.y - 0.5 * height_m, c.x + 0.5 * width_m, c.y + 0.5 * height_m};
}

Rect ChargerBody::bounding_box() const {
  const double c = std::fabs(std::cos(yaw)), s = std::fabs(std::sin(yaw));
  const double ex = c * half_depth_m + s * half_width_m;
  const double ey = s * half_depth_m + c * half_width_m;
  return {center.x - ex, center.y - ey, center.x + ex, center.y + ey};
}

ChargerBody charger_body(const World& world) { return charger_body(world, world.charger); }

ChargerBody charger_body(const World& world, const Pose2& docked) {
  const Vec2 ahead = docked.heading();
  const double half_depth = 0.5 * world.charger_spec.depth_m;
  const Vec2 center = docked.position() + (world.robot.front_extent_m() + half_depth) * ahead;
  return {center, half_depth, 0.5 * world.charger_spec.width_m, docked.yaw};
}

Pose2 staging_pose(const World& world) {
  const Vec2 p =
      world.charger.position() - world.charger_spec.staging_distance_m * world.charger.heading();
  return {p.x, p.y, world.charger.yaw};
}

bool differs_from_map(const World& plant) {
  const Pose2& o = plant.charger_map_offset;
  return !plant.unmapped.empty() || o.x != 0 || o.y != 0 || o.yaw != 0;
}

Pose2 robot_map_charger(const World& plant) {
  const Pose2& o = plant.charger_map_offset;
  return {plant.charger.x + o.x, plant.charger.y + o.y,
          geom::wrap_angle(plant.charger.yaw + o.yaw)};
}

World robot_map(const World& plant) {
  World map = plant;
  map.unmapped.clear();
  map.charger = robot_map_charger(plant);
  map.charger_map_offset = {0.0, 0.0, 0.0};
  return map;
}

}  // namespace plantsim::worlds
