// A local distance field for sampling controllers (MPPI, DWB): each cell of a square window
// around the robot holds the distance from its centre to the nearest box the robot knows of
// (its map's and what it sensed), up to a reach, so a trajectory's thousands of points each cost
// one array read. Outside the window, or outside the floor, the distance is 0: unknown is not
// free.
#pragma once

#include <cmath>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::controller {

class ClearanceGrid {
 public:
  /// The window of half side `half_side_m` around `center`, in cells of `cell_m`; `boxes` are
  /// the obstacles, `floor` the area inside the walls. Distances beyond `reach_m` are held as
  /// `reach_m` (a controller that looks no further than its inflation asks no more).
  ClearanceGrid(geom::Vec2 center, double half_side_m, double cell_m,
                const std::vector<geom::Rect>& boxes, const geom::Rect& floor,
                double reach_m = INFINITY);

  /// Distance (m) from (x, y) to the nearest box or wall, as the point's cell holds it.
  float at(float x, float y) const {
    const float fx = (x - x0_) * inverse_cell_, fy = (y - y0_) * inverse_cell_;
    if (!(fx >= 0.0f && fy >= 0.0f && fx < static_cast<float>(n_) && fy < static_cast<float>(n_)))
      return 0.0f;
    return cells_[static_cast<std::size_t>(static_cast<int>(fy) * n_ + static_cast<int>(fx))];
  }
  /// The same distance interpolated between the four nearest cell centres: within a few
  /// millimetres of the exact distance where `at` may be off by half a cell's diagonal, for a
  /// collision test that rejects only what really touches.
  float interpolated(float x, float y) const;
  double cell_m() const { return cell_; }

 private:
  float x0_, y0_, inverse_cell_;
  double cell_;
  int n_;
  std::vector<float> cells_;
};

}  // namespace plantsim::controller
