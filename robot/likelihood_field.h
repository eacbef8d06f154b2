// The particle filter's likelihood field: for every point of the floor, the distance to the
// nearest mapped surface (the outlines of the mapped rectangles, the floor's walls and the
// charger block), exact at the cells' centres within `reach_m` of a surface and signed (negative
// inside a solid block, beyond a wall), so that interpolating it between the centres is exact
// across a flat surface: the field places a surface where the map has it, not half a cell off
// (the scan matcher's grid, built for a coarse search, does). Robot side: the map only.
#pragma once

#include <vector>

#include "geometry/vec2.h"
#include "worlds/world.h"

namespace plantsim::robot {

class LikelihoodField {
 public:
  /// A grid of `resolution_m` over the floor and a margin (coarser beyond `max_cells`).
  explicit LikelihoodField(const worlds::World& map, double resolution_m = 0.05,
                           double reach_m = 1.0, long max_cells = 8'000'000);
  /// Distance from `p` to the nearest mapped surface (bilinear between the cells' centres),
  /// negative inside a block, at most reach_m in size; reach_m off the grid.
  double distance(geom::Vec2 p) const;
  double resolution_m() const { return res_; }
  double reach_m() const { return reach_; }

 private:
  void add_outline(const geom::Rect& r, bool solid);
  float at(long i, long j) const {
    return i >= 0 && j >= 0 && i < nx_ && j < ny_ ? cells_[static_cast<std::size_t>(j * nx_ + i)]
                                                  : static_cast<float>(reach_);
  }

  double res_ = 0.05, reach_ = 1.0;
  geom::Vec2 origin_;  // lower left corner of cell (0, 0)
  long nx_ = 0, ny_ = 0;
  std::vector<float> cells_;           // unsigned distance, capped at reach_
  std::vector<unsigned char> inside_;  // the cell's centre is inside a block (or off the floor)
};

}  // namespace plantsim::robot
