// Derived charger geometry of a World.
#include "worlds/world.h"

#include <algorithm>
#include <cmath>

namespace plantsim::worlds {

Rect ChargerBody::bounding_box() const {
  const double c = std::fabs(std::cos(yaw)), s = std::fabs(std::sin(yaw));
  const double ex = c * half_depth_m + s * half_width_m;
  const double ey = s * half_depth_m + c * half_width_m;
  return {center.x - ex, center.y - ey, center.x + ex, center.y + ey};
}

ChargerBody charger_body(const World& world) {
  const Vec2 ahead = world.charger.heading();
  const double half_depth = 0.5 * world.charger_spec.depth_m;
  const Vec2 center = world.charger.position() + (world.robot.radius_m + half_depth) * ahead;
  return {center, half_depth, 0.5 * world.charger_spec.width_m, world.charger.yaw};
}

Pose2 staging_pose(const World& world) {
  const Vec2 p = world.charger.position() -
                 world.charger_spec.staging_distance_m * world.charger.heading();
  return {p.x, p.y, world.charger.yaw};
}

}  // namespace plantsim::worlds
