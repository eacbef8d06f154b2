// The map's static parts for expected ranges.
#include "robot/map_raycaster.h"

#include <algorithm>

#include "robot/near_rasters.h"

namespace plantsim::robot {

MapRaycaster::MapRaycaster(const worlds::World& map) : surfaces_(map) {}

std::optional<RayHit> MapRaycaster::cast(geom::Vec2 from, double angle_rad,
                                         double max_range_m) const {
  return surfaces_.cast(from, geom::unit_from_angle(angle_rad), max_range_m);
}

void MapRaycaster::cast_fan(geom::Vec2 from, std::span<const geom::Vec2> directions,
                            double first_angle, double increment, double max_range_m,
                            std::vector<std::optional<RayHit>>& hits) const {
  surfaces_.cast_fan(from, directions, first_angle, increment, max_range_m, hits);
}

const geom::NearRaster& MapRaycaster::raster_for(double margin_m) const {
  if (!near_.empty() && near_.front()->margin_m() == margin_m) return *near_.front();  // per scan
  for (std::size_t i = 0; i < near_.size(); ++i)
    if (near_[i]->margin_m() == margin_m) {
      std::rotate(near_.begin(), near_.begin() + static_cast<std::ptrdiff_t>(i),
                  near_.begin() + static_cast<std::ptrdiff_t>(i) + 1);  // to the front
      return *near_.front();
    }
  if (near_.size() == kRasters) near_.pop_back();
  near_.insert(near_.begin(), shared_near_raster(surfaces_.grid(), margin_m));
  return *near_.front();
}

}  // namespace plantsim::robot
