// Box buckets: counted in one pass, filled in a second (no per-bucket vectors).
#include "planner/mesh/box_buckets.h"

#include <algorithm>
#include <cmath>

namespace plantsim::planner {

BoxBuckets::BoxBuckets(const std::vector<Box>& boxes, double eps) {
  if (boxes.empty()) return;
  double x0 = boxes[0].xlo, y0 = boxes[0].ylo, x1 = boxes[0].xhi, y1 = boxes[0].yhi;
  for (const Box& c : boxes)
    x0 = std::min(x0, c.xlo), y0 = std::min(y0, c.ylo), x1 = std::max(x1, c.xhi),
    y1 = std::max(y1, c.yhi);
  const double w = x1 - x0, h = y1 - y0;
  size_ = std::max(std::sqrt(w * h / static_cast<double>(boxes.size())), 1e-6 * std::max(w, h));
  if (!(size_ > 0)) size_ = 1;
  nx_ = std::clamp(static_cast<int>(std::ceil(w / size_)), 1, 4096);
  ny_ = std::clamp(static_cast<int>(std::ceil(h / size_)), 1, 4096);
  size_ = std::max({size_, w / nx_, h / ny_});
  x0_ = x0, y0_ = y0;
  const auto bx = [&](double x) {
    return std::clamp(static_cast<int>((x - x0_) / size_), 0, nx_ - 1);
  };
  const auto by = [&](double y) {
    return std::clamp(static_cast<int>((y - y0_) / size_), 0, ny_ - 1);
  };
  std::vector<std::int32_t> count(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const Box& c = boxes[i];
      for (int v = by(c.ylo - eps); v <= by(c.yhi + eps); ++v)
        for (int u = bx(c.xlo - eps); u <= bx(c.xhi + eps); ++u) {
          const std::size_t b = static_cast<std::size_t>(v) * nx_ + u;
          if (pass == 0)
            ++count[b + 1];
          else
            index_[start_[b] + count[b]++] = static_cast<std::int32_t>(i);
        }
    }
    if (pass == 0) {
      for (std::size_t b = 1; b < count.size(); ++b) count[b] += count[b - 1];
      start_ = count;
      index_.resize(static_cast<std::size_t>(count.back()));
      std::fill(count.begin(), count.end(), 0);
    }
  }
}

BoxBuckets::Span BoxBuckets::near(geom::Vec2 p) const {
  if (start_.empty() || !std::isfinite(p.x) || !std::isfinite(p.y)) return {nullptr, nullptr};
  const int u = std::clamp(static_cast<int>((p.x - x0_) / size_), 0, nx_ - 1);
  const int v = std::clamp(static_cast<int>((p.y - y0_) / size_), 0, ny_ - 1);
  const std::size_t b = static_cast<std::size_t>(v) * nx_ + u;
  return {index_.data() + start_[b], index_.data() + start_[b + 1]};
}

}  // namespace plantsim::planner
