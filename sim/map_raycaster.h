// The robot's map as something to cast rays through: the mapped obstacle rectangles, floor
// walls and the charger at its mapped pose, in a grid of their own (box2d_scene.h's
// StaticScene, exact ray casts by geometry; never the physics world). The estimator predicts
// lidar ranges with it; perception asks it which returns the map explains.
#pragma once

#include <memory>
#include <optional>

#include "sim/ray_hit.h"
#include "worlds/world.h"

namespace plantsim::sim {
namespace detail {
struct StaticScene;
}

class MapRaycaster {
 public:
  /// `map` is the plant as the robot knows it (its obstacles, floor and charger pose).
  explicit MapRaycaster(const worlds::World& map);
  ~MapRaycaster();
  MapRaycaster(const MapRaycaster&) = delete;
  MapRaycaster& operator=(const MapRaycaster&) = delete;

  /// Nearest mapped surface along the ray from `from` in direction `angle_rad`, within `max_range_m`.
  std::optional<RayHit> cast(geom::Vec2 from, double angle_rad, double max_range_m) const;
  /// True when some mapped surface lies within `margin_m` (per axis) of `point`.
  bool surface_near(geom::Vec2 point, double margin_m) const;

 private:
  std::unique_ptr<detail::StaticScene> scene_;
};

}  // namespace plantsim::sim
