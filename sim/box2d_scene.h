// Internal to sim/: building a Box2D scene of the plant's static parts (obstacle rectangles,
// floor walls, charger block) and casting rays through its broad phase. Used by the physics
// (the real plant) and by the estimator's map (the plant as the robot believes it is).
#pragma once

#include <box2d/box2d.h>

#include <optional>
#include <span>
#include <vector>

#include "geometry/ray_grid.h"

#include "sim/ray_hit.h"
#include "worlds/world.h"

namespace plantsim::sim::detail {

enum FixtureTag : std::uintptr_t { kObstacle = 1, kWall = 2, kCharger = 3, kRobot = 4, kMoving = 5, kTarget = 6 };

inline FixtureTag tag_of(b2Fixture* f) { return static_cast<FixtureTag>(f->GetUserData().pointer); }

/// Adds every obstacle rectangle and the four floor walls as fixtures of one static body, and
/// the charger block as its own static body.
void add_static_scene(b2World& world, const worlds::World& plant);

/// Nearest hit along the segment from `from` to `to`, ignoring the robot's own fixture.
std::optional<RayHit> cast_ray(const b2World& world, geom::Vec2 from, geom::Vec2 to);

/// The same static parts as add_static_scene (obstacles, unmapped obstacles, floor walls, the
/// charger block where the physics holds it) for exact ray casts by geometry (geometry/ray_grid.h),
/// each box with the kind of surface it is.
struct StaticScene {
  explicit StaticScene(const worlds::World& plant);
  std::optional<RayHit> cast(geom::Vec2 from, geom::Vec2 direction, double max_range_m) const;
  /// A fan of rays at once (geom::RayGrid::cast_fan): hits[k] as cast(from, directions[k], ...).
  void cast_fan(geom::Vec2 from, std::span<const geom::Vec2> directions, double first_angle, double increment,
                double max_range_m, std::vector<std::optional<RayHit>>& hits) const;
  geom::RayGrid grid;
  std::vector<SurfaceKind> kinds;  // per box, in the grid's order
};

}  // namespace plantsim::sim::detail
