// The particle filter's likelihood field: for every point of the floor, the distance to the
// nearest mapped surface (the outlines of the mapped rectangles, the floor's walls and the
// charger block), exact at the cells' centres within `reach_m` of a surface and signed (negative
// inside a solid block, beyond a wall), so that interpolating it between the centres is exact
// across a flat surface: the field places a surface where the map has it, not half a cell off
// (the scan matcher's grid, built for a coarse search, does). Robot side: the map only.
#pragma once

#include <cmath>
#include <memory>

#include "geometry/vec2.h"
#include "util/huge_page_block.h"
#include "worlds/world.h"

namespace plantsim::robot {

class LikelihoodField {
 public:
  /// A grid of `resolution_m` over the floor and a margin (coarser beyond `max_cells`).
  explicit LikelihoodField(const worlds::World& map, double resolution_m = 0.05,
                           double reach_m = 1.0, long max_cells = 8'000'000);
  /// Distance from `p` to the nearest mapped surface (bilinear between the cells' centres),
  /// negative inside a block, at most reach_m in size; reach_m off the grid. Inline: the particle
  /// filter asks it for every beam of every particle.
  double distance(geom::Vec2 p) const {
    const double u = (p.x - origin_.x) * per_m_ - 0.5, v = (p.y - origin_.y) * per_m_ - 0.5;
    const double fu = std::floor(u), fv = std::floor(v);
    const long i = static_cast<long>(fu), j = static_cast<long>(fv);
    const double a = u - fu, b = v - fv;
    if (i >= 0 && j >= 0 && i + 1 < nx_ && j + 1 < ny_) {
      const float* row = cells_ + j * nx_ + i;
      return (1 - b) * ((1 - a) * static_cast<double>(row[0]) + a * static_cast<double>(row[1])) +
             b * ((1 - a) * static_cast<double>(row[nx_]) + a * static_cast<double>(row[nx_ + 1]));
    }
    return (1 - b) * ((1 - a) * at(i, j) + a * at(i + 1, j)) +
           b * ((1 - a) * at(i, j + 1) + a * at(i + 1, j + 1));
  }
  double resolution_m() const { return res_; }
  double reach_m() const { return reach_; }

 private:
  void add_outline(const geom::Rect& r, bool solid);
  double at(long i, long j) const {
    return i >= 0 && j >= 0 && i < nx_ && j < ny_
               ? static_cast<double>(cells_[static_cast<std::size_t>(j * nx_ + i)])
               : reach_;
  }

  double res_ = 0.05, reach_ = 1.0;
  double per_m_ = 20;  // cells per metre, 1 / res_
  geom::Vec2 origin_;  // lower left corner of cell (0, 0)
  long nx_ = 0, ny_ = 0;
  util::HugePageBlock storage_;
  float* cells_ = nullptr;  // nx_ * ny_ signed distances in storage_, row by row
};

/// The field of `map` at `resolution_m`, shared by every episode of the process that asks for
/// the same map at the same resolution: a batch's episodes on one plant build it once (on a
/// 100 x 60 m floor at 5 cm it is 10 MB, and building it cost 7 % of a particle filter episode).
/// The fields of the last few maps asked for are kept; thread-safe.
std::shared_ptr<const LikelihoodField> shared_likelihood_field(const worlds::World& map,
                                                               double resolution_m);

}  // namespace plantsim::robot
