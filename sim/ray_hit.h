// What a ray cast through a Box2D scene returns: the nearest surface hit, its outward normal
// and what kind of thing it belongs to. Shared by the sensors (through the physics) and the
// estimator (through its map); Box2D types stay behind it.
#pragma once

#include "geometry/vec2.h"

namespace plantsim::sim {

enum class SurfaceKind { kObstacle, kWall, kCharger, kMoving, kTarget };

struct RayHit {
  geom::Vec2 point;   ///< world frame
  geom::Vec2 normal;  ///< unit, pointing out of the surface (towards the ray's origin side)
  double range_m;     ///< distance from the ray's origin
  SurfaceKind kind;
};

}  // namespace plantsim::sim
