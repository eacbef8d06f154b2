// The plant's static surfaces as boxes, exactly where the physics builds them: obstacle
// rectangles, unmapped obstacles, the floor's walls and the charger's rigid block (set back from
// its nominal body by the physics' contact skin and half the pads' spring travel). One list for
// the physics' lidar and for the robot's map of the plant, cast through one exact grid.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "geometry/ray_grid.h"
#include "worlds/world.h"

namespace plantsim::worlds {

/// Box2D's polygon skin (b2_polygonRadius, two linear slops, in single precision): contacts
/// settle this far outside a body's faces. sim/box2d_scene.cpp checks it against Box2D's own.
inline constexpr double kContactSkinM = static_cast<double>(2.0f * 0.005f);

enum class SurfaceKind { kObstacle, kWall, kCharger, kMoving, kTarget };

/// What a ray cast returns: the nearest surface hit, its outward normal and what it belongs to.
struct RayHit {
  geom::Vec2 point;   ///< world frame
  geom::Vec2 normal;  ///< unit, pointing out of the surface (towards the ray's origin side)
  double range_m;     ///< distance from the ray's origin
  SurfaceKind kind;
};

/// The charger's rigid block where the physics holds it: the nominal body (charger_body) moved
/// out along the approach axis by the contact skin and half the pads' travel.
geom::OrientedBox charger_block(const World& plant);

/// Every static box of `plant` in one exact ray-casting grid, each with its kind.
class SurfaceGrid {
 public:
  explicit SurfaceGrid(const World& plant);

  std::optional<RayHit> cast(geom::Vec2 from, geom::Vec2 direction, double max_range_m) const;
  /// A fan of rays at once (geom::RayGrid::cast_fan): hits[k] as cast(from, directions[k], ...).
  void cast_fan(geom::Vec2 from, std::span<const geom::Vec2> directions, double first_angle,
                double increment, double max_range_m,
                std::vector<std::optional<RayHit>>& hits) const;
  /// The same fan's answers as the grid gives them (ranges, normals, box indices), without
  /// building a RayHit per ray; valid until the next fan.
  const geom::FanHits& fan(geom::Vec2 from, std::span<const geom::Vec2> directions,
                           double first_angle, double increment, double max_range_m) const {
    grid_.cast_fan(from, directions, first_angle, increment, max_range_m, scratch_);
    return scratch_;
  }
  const geom::RayGrid& grid() const { return grid_; }

 private:
  geom::RayGrid grid_;
  std::vector<SurfaceKind> kinds_;  // per box, in the grid's order
  mutable geom::FanHits scratch_;
};

}  // namespace plantsim::worlds
