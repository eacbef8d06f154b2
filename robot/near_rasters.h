// The map-nearness rasters of a process, shared by its episodes: a batch runs hundreds of
// episodes on one map, and each built the same few rasters afresh (2.5 % of a world_N200
// episode). A raster is read-only once built, so threads share it as they share the map.
#pragma once

#include <memory>

#include "geometry/near_raster.h"
#include "geometry/ray_grid.h"

namespace plantsim::robot {

/// The raster answering "within `margin_m` of one of `grid`'s boxes?" over the grid's area grown
/// by the margin, in cells of max(5 cm, margin / 2): built once per set of boxes and margin, the
/// last few kept for the process.
std::shared_ptr<const geom::NearRaster> shared_near_raster(const geom::RayGrid& grid,
                                                           double margin_m);

}  // namespace plantsim::robot
