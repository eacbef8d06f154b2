// Rasterising each box grown by the margin: cells wholly inside say yes, cells it only touches
// say "depends".
#include "geometry/near_raster.h"

#include <algorithm>
#include <cmath>

namespace plantsim::geom {

NearRaster::NearRaster(const std::vector<Rect>& boxes, double margin_m, Rect area, double cell_m,
                       long max_cells)
    : margin_(margin_m), area_(area) {
  const double w = std::max(area.width(), 1e-6), h = std::max(area.height(), 1e-6);
  cell_ = std::max(cell_m, std::sqrt(w * h / static_cast<double>(std::max(1L, max_cells))));
  nx_ = std::max(1L, static_cast<long>(std::ceil(w / cell_)));
  ny_ = std::max(1L, static_cast<long>(std::ceil(h / cell_)));
  inverse_cell_ = 1.0 / cell_;
  static_assert(static_cast<int>(Answer::kNo) == 0);
  cells_.assign((static_cast<std::size_t>(nx_ * ny_) + 3) / 4, 0);
  for (const Rect& b : boxes) {
    const Rect grown{b.xmin - margin_m, b.ymin - margin_m, b.xmax + margin_m, b.ymax + margin_m};
    // Cells the grown box touches, and one more on each side: a point on a cell's edge, or a
    // division rounded across one, must never find a "no" beside a box.
    const long i0 =
        std::max(0L, static_cast<long>(std::floor((grown.xmin - area_.xmin) / cell_)) - 1);
    const long i1 =
        std::min(nx_ - 1, static_cast<long>(std::floor((grown.xmax - area_.xmin) / cell_)) + 1);
    const long j0 =
        std::max(0L, static_cast<long>(std::floor((grown.ymin - area_.ymin) / cell_)) - 1);
    const long j1 =
        std::min(ny_ - 1, static_cast<long>(std::floor((grown.ymax - area_.ymin) / cell_)) + 1);
    for (long j = j0; j <= j1; ++j)
      for (long i = i0; i <= i1; ++i) {
        const std::size_t c = static_cast<std::size_t>(j * nx_ + i);
        if (get(c) == Answer::kYes) continue;
        // Wholly inside, with a cell's rounding to spare on each side.
        const double x0 = area_.xmin + static_cast<double>(i) * cell_,
                     y0 = area_.ymin + static_cast<double>(j) * cell_;
        const double slack = 1e-9 * (1.0 + std::fabs(x0) + std::fabs(y0) + cell_);
        const bool inside = grown.xmin <= x0 - slack && x0 + cell_ + slack <= grown.xmax &&
                            grown.ymin <= y0 - slack && y0 + cell_ + slack <= grown.ymax;
        set(c, inside ? Answer::kYes : Answer::kDepends);
      }
  }
}

}  // namespace plantsim::geom
