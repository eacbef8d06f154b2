// The map's static parts for expected ranges.
#include "sim/map_raycaster.h"

#include "sim/box2d_scene.h"

namespace plantsim::sim {

MapRaycaster::MapRaycaster(const worlds::World& map) : scene_(std::make_unique<detail::StaticScene>(map)) {}

MapRaycaster::~MapRaycaster() = default;

std::optional<RayHit> MapRaycaster::cast(geom::Vec2 from, double angle_rad, double max_range_m) const {
  return scene_->cast(from, geom::unit_from_angle(angle_rad), max_range_m);
}

bool MapRaycaster::surface_near(geom::Vec2 point, double margin_m) const {
  // Per axis: the rectangles themselves, the charger's oriented block by its bounding box.
  return scene_->grid.near(point, margin_m);
}

}  // namespace plantsim::sim
