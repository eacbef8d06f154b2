// Internal to sim/: building a Box2D scene of the plant's static parts (obstacle rectangles,
// floor walls, charger block, as worlds/surfaces.h lists them) and Box2D's own ray cast through
// its broad phase (the reference the exact casts are measured against).
#pragma once

#include <box2d/box2d.h>

#include <optional>

#include "worlds/surfaces.h"
#include "worlds/world.h"

namespace plantsim::sim::detail {

enum FixtureTag : std::uintptr_t {
  kObstacle = 1,
  kWall = 2,
  kCharger = 3,
  kRobot = 4,
  kMoving = 5,
  kTarget = 6
};

inline FixtureTag tag_of(b2Fixture* f) { return static_cast<FixtureTag>(f->GetUserData().pointer); }

/// Adds every obstacle rectangle and the four floor walls as fixtures of one static body, and
/// the charger block as its own static body.
void add_static_scene(b2World& world, const worlds::World& plant);

/// Nearest hit along the segment from `from` to `to`, ignoring the robot's own fixture.
std::optional<worlds::RayHit> cast_ray(const b2World& world, geom::Vec2 from, geom::Vec2 to);

}  // namespace plantsim::sim::detail
