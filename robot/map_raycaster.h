// The robot's map as something to cast rays through: the mapped obstacle rectangles, floor
// walls and the charger at its mapped pose, in a grid of their own (worlds/surfaces.h, exact
// ray casts by geometry; never the physics world). The estimator predicts
// lidar ranges with it; perception asks it which returns the map explains.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "geometry/near_raster.h"
#include "worlds/surfaces.h"
#include "worlds/world.h"

namespace plantsim::robot {
using worlds::RayHit;

class MapRaycaster {
 public:
  /// `map` is the plant as the robot knows it (its obstacles, floor and charger pose).
  explicit MapRaycaster(const worlds::World& map);
  MapRaycaster(const MapRaycaster&) = delete;
  MapRaycaster& operator=(const MapRaycaster&) = delete;

  /// Nearest mapped surface along the ray from `from` in direction `angle_rad`, within
  /// `max_range_m`.
  std::optional<RayHit> cast(geom::Vec2 from, double angle_rad, double max_range_m) const;
  /// A fan of rays from `from` (unit directions[k] at angle first_angle + k * increment, to 1e-6
  /// rad): hits[k] as cast() finds along it, the boxes within reach visited once.
  void cast_fan(geom::Vec2 from, std::span<const geom::Vec2> directions, double first_angle,
                double increment, double max_range_m,
                std::vector<std::optional<RayHit>>& hits) const;
  /// "Does some mapped surface lie within the margin (per axis) of this point?" for one margin,
  /// asked of many points (a scan's returns): a raster made once per margin answers most of
  /// them, the grid settles the cells it cannot.
  class SurfaceNear {
   public:
    bool operator()(geom::Vec2 point) const {
      switch (raster_.at(point)) {
        case geom::NearRaster::Answer::kYes:
          return true;
        case geom::NearRaster::Answer::kNo:
          return false;
        case geom::NearRaster::Answer::kDepends:
          break;
      }
      return grid_.near(point, raster_.margin_m());
    }

   private:
    friend class MapRaycaster;
    SurfaceNear(const geom::NearRaster& raster, const geom::RayGrid& grid)
        : raster_(raster), grid_(grid) {}
    const geom::NearRaster& raster_;
    const geom::RayGrid& grid_;
  };
  /// Per axis: the rectangles themselves, the charger's oriented block by its bounding box.
  /// Valid until surface_near is asked for other margins (a raster may then be dropped).
  SurfaceNear surface_near(double margin_m) const {
    return {raster_for(margin_m), surfaces_.grid()};
  }

 private:
  worlds::SurfaceGrid surfaces_;
  // One raster per margin asked (a learnt noise moves the margin between a few values), the
  // least recently used dropped beyond kRasters; each taken from the process's rasters of the
  // same map and margin when another episode has built it (near_rasters.h).
  static constexpr std::size_t kRasters = 4;
  mutable std::vector<std::shared_ptr<const geom::NearRaster>> near_;
  const geom::NearRaster& raster_for(double margin_m) const;
};

}  // namespace plantsim::robot
