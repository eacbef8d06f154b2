// The distance field (see the header): each cell's distance computed exactly from the boxes
// near the window only, so a plant of thousands of boxes costs what its neighbourhood costs.
#include "controller/clearance_grid.h"

#include <algorithm>
#include <cmath>

#include "geometry/clearance.h"

namespace plantsim::controller {

ClearanceGrid::ClearanceGrid(geom::Vec2 center, double half_side_m, double cell_m,
                             const std::vector<geom::Rect>& boxes, const geom::Rect& floor)
    : x0_(static_cast<float>(center.x - half_side_m)),
      y0_(static_cast<float>(center.y - half_side_m)),
      inverse_cell_(static_cast<float>(1.0 / cell_m)),
      cell_(cell_m),
      n_(std::max(1, static_cast<int>(std::ceil(2.0 * half_side_m / cell_m)))) {
  // Beyond this a box cannot be any cell's nearest: every cell is within the window's diagonal
  // of the window's walls.
  const geom::Rect window{center.x - half_side_m, center.y - half_side_m, center.x + half_side_m,
                          center.y + half_side_m};
  std::vector<geom::Rect> near;
  for (const geom::Rect& b : boxes)
    if (b.xmax >= window.xmin - 2 * half_side_m && b.xmin <= window.xmax + 2 * half_side_m &&
        b.ymax >= window.ymin - 2 * half_side_m && b.ymin <= window.ymax + 2 * half_side_m)
      near.push_back(b);
  cells_.assign(static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_), 0.0f);
  for (int j = 0; j < n_; ++j)
    for (int i = 0; i < n_; ++i) {
      const geom::Vec2 p{window.xmin + (i + 0.5) * cell_m, window.ymin + (j + 0.5) * cell_m};
      double d = 0;
      if (p.x > floor.xmin && p.x < floor.xmax && p.y > floor.ymin && p.y < floor.ymax) {
        d = std::min({p.x - floor.xmin, floor.xmax - p.x, p.y - floor.ymin, floor.ymax - p.y});
        for (const geom::Rect& b : near) d = std::min(d, geom::distance_to_rect(p, b));
      }
      cells_[static_cast<std::size_t>(j * n_ + i)] = static_cast<float>(d);
    }
}

float ClearanceGrid::interpolated(float x, float y) const {
  // Cell centres sit at half cells; outside the window it is 0 as `at` says.
  const float fx = (x - x0_) * inverse_cell_ - 0.5f, fy = (y - y0_) * inverse_cell_ - 0.5f;
  const auto n = static_cast<float>(n_);
  if (!(fx >= -0.5f && fy >= -0.5f && fx < n - 0.5f && fy < n - 0.5f)) return 0.0f;
  const float cx = std::clamp(fx, 0.0f, n - 1.0f), cy = std::clamp(fy, 0.0f, n - 1.0f);
  const int i = std::min(static_cast<int>(cx), n_ - 2), j = std::min(static_cast<int>(cy), n_ - 2);
  if (n_ < 2) return cells_[0];
  const float u = cx - static_cast<float>(i), v = cy - static_cast<float>(j);
  const auto cell = [&](int a, int b) { return cells_[static_cast<std::size_t>(b * n_ + a)]; };
  return (1 - v) * ((1 - u) * cell(i, j) + u * cell(i + 1, j)) +
         v * ((1 - u) * cell(i, j + 1) + u * cell(i + 1, j + 1));
}

}  // namespace plantsim::controller
