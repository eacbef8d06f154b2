// The distance field (see the header): each cell's distance computed exactly, from the walls
// and then box by box over only the cells within the field's reach of the box, so a cycle costs
// the area the boxes near the robot sweep, not every cell times every box.
#include "controller/clearance_grid.h"

#include <algorithm>
#include <cmath>

#include "geometry/clearance.h"

namespace plantsim::controller {

ClearanceGrid::ClearanceGrid(geom::Vec2 center, double half_side_m, double cell_m,
                             const std::vector<geom::Rect>& boxes, const geom::Rect& floor,
                             double reach_m)
    : x0_(static_cast<float>(center.x - half_side_m)),
      y0_(static_cast<float>(center.y - half_side_m)),
      inverse_cell_(static_cast<float>(1.0 / cell_m)),
      cell_(cell_m),
      n_(std::max(1, static_cast<int>(std::ceil(2.0 * half_side_m / cell_m)))) {
  const double xmin = center.x - half_side_m, ymin = center.y - half_side_m;
  // Beyond the window's diagonal no distance can be the nearest: the reach never need exceed it.
  const double reach = std::min(reach_m, 2.0 * std::sqrt(2.0) * half_side_m);
  cells_.assign(static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_), 0.0f);
  for (int j = 0; j < n_; ++j)
    for (int i = 0; i < n_; ++i) {
      const geom::Vec2 p{xmin + (i + 0.5) * cell_m, ymin + (j + 0.5) * cell_m};
      double d = 0;
      if (p.x > floor.xmin && p.x < floor.xmax && p.y > floor.ymin && p.y < floor.ymax)
        d = std::min(
            {p.x - floor.xmin, floor.xmax - p.x, p.y - floor.ymin, floor.ymax - p.y, reach});
      cells_[static_cast<std::size_t>(j * n_ + i)] = static_cast<float>(d);
    }
  // Each box lowers only the cells within the reach of it (the others keep what they hold).
  const auto first = [&](double v, double lo) {
    return std::clamp(static_cast<int>(std::floor((v - lo) / cell_m - 0.5)), 0, n_);
  };
  const auto last = [&](double v, double lo) {
    return std::clamp(static_cast<int>(std::ceil((v - lo) / cell_m - 0.5)), -1, n_ - 1);
  };
  for (const geom::Rect& b : boxes) {
    const int i0 = first(b.xmin - reach, xmin), i1 = last(b.xmax + reach, xmin);
    const int j0 = first(b.ymin - reach, ymin), j1 = last(b.ymax + reach, ymin);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        float& c = cells_[static_cast<std::size_t>(j * n_ + i)];
        const geom::Vec2 p{xmin + (i + 0.5) * cell_m, ymin + (j + 0.5) * cell_m};
        c = std::min(c, static_cast<float>(geom::distance_to_rect(p, b)));
      }
  }
}

float ClearanceGrid::interpolated(float x, float y) const {
  // Cell centres sit at half cells; outside the window it is 0 as `at` says.
  const float fx = (x - x0_) * inverse_cell_ - 0.5f, fy = (y - y0_) * inverse_cell_ - 0.5f;
  const auto n = static_cast<float>(n_);
  if (!(fx >= -0.5f && fy >= -0.5f && fx < n - 0.5f && fy < n - 0.5f)) return 0.0f;
  if (n_ < 2) return cells_[0];
  const float cx = std::clamp(fx, 0.0f, n - 1.0f), cy = std::clamp(fy, 0.0f, n - 1.0f);
  const int i = std::min(static_cast<int>(cx), n_ - 2), j = std::min(static_cast<int>(cy), n_ - 2);
  const float u = cx - static_cast<float>(i), v = cy - static_cast<float>(j);
  const auto cell = [&](int a, int b) { return cells_[static_cast<std::size_t>(b * n_ + a)]; };
  return (1 - v) * ((1 - u) * cell(i, j) + u * cell(i + 1, j)) +
         v * ((1 - u) * cell(i, j + 1) + u * cell(i + 1, j + 1));
}

}  // namespace plantsim::controller
