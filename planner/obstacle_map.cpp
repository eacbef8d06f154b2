// Grid construction, pinch-point discovery and the exact segment test.
#include "planner/obstacle_map.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "geometry/predicates.h"
#include "planner/inflation.h"

namespace plantsim::planner {
namespace {

constexpr int kMaxCellsPerSide = 2048;

}  // namespace

ObstacleMap::ObstacleMap(std::vector<Rect> inflated, const Rect& floor, double wall_inflation)
    : rects_(std::move(inflated)) {
  // Exact duplicates would hide each other's corners in the quadrant test.
  std::sort(rects_.begin(), rects_.end(), [](const Rect& a, const Rect& b) {
    return std::tie(a.xmin, a.ymin, a.xmax, a.ymax) < std::tie(b.xmin, b.ymin, b.xmax, b.ymax);
  });
  rects_.erase(std::unique(rects_.begin(), rects_.end()), rects_.end());
  obstacle_count_ = rects_.size();

  // Walls grow inward like obstacles (rounded outward from the walls' side).
  const Rect inner = floor.inflated(-wall_inflation);
  const double k = 1.0 / kInflationLattice_m;
  free_floor_ = {std::ceil(inner.xmin * k) / k, std::ceil(inner.ymin * k) / k,
                 std::floor(inner.xmax * k) / k, std::floor(inner.ymax * k) / k};
  const double t = std::max(1.0, wall_inflation);  // thickness beyond the free floor
  const Rect& f = free_floor_;
  for (const Rect& wall : geom::surrounding_walls(f, t)) rects_.push_back(wall);

  const double w = std::max(f.width(), 1e-3), h = std::max(f.height(), 1e-3);
  const double n = static_cast<double>(std::max<std::size_t>(obstacle_count_, 1));
  cell_size_ = std::max({std::sqrt(w * h / n), w / kMaxCellsPerSide, h / kMaxCellsPerSide});
  x0_ = f.xmin;
  y0_ = f.ymin;
  nx_ = std::max(1, static_cast<int>(std::ceil(w / cell_size_)));
  ny_ = std::max(1, static_cast<int>(std::ceil(h / cell_size_)));
  cells_.assign(static_cast<std::size_t>(nx_) * ny_, Cell{});
  for (std::size_t i = 0; i < rects_.size(); ++i) {
    const Rect& r = rects_[i];
    if (r.xmax < f.xmin || r.xmin > f.xmax || r.ymax < f.ymin || r.ymin > f.ymax) continue;
    for (int cy = cell_y(r.ymin); cy <= cell_y(r.ymax); ++cy)
      for (int cx = cell_x(r.xmin); cx <= cell_x(r.xmax); ++cx)
        cells_[static_cast<std::size_t>(cy) * nx_ + cx].rects.push_back(
            static_cast<std::int32_t>(i));
  }
  find_pinch_points();
}

int ObstacleMap::cell_x(double x) const {
  const int c = static_cast<int>(std::floor((x - x0_) / cell_size_));
  return std::clamp(c, 0, nx_ - 1);
}

int ObstacleMap::cell_y(double y) const {
  const int c = static_cast<int>(std::floor((y - y0_) / cell_size_));
  return std::clamp(c, 0, ny_ - 1);
}

bool ObstacleMap::quadrant_occupied(Vec2 c, int sx, int sy, std::int32_t self) const {
  for (std::int32_t i : cell(cell_x(c.x), cell_y(c.y)).rects)
    if (i != self && geom::occupies_quadrant(rects_[i], c, sx, sy)) return true;
  return false;
}

void ObstacleMap::find_pinch_points() {
  // A pinch is a corner point where two diagonally opposite quadrants are filled and the other
  // two free: a segment could cross there from one free quadrant to the other touching the
  // rectangles only at their corners, so every segment with the point in its interior is
  // refused there. A concave corner (three quadrants filled) is not one: a segment through it
  // runs into a rectangle's interior or between two rectangles along their shared edge, which
  // the other tests refuse.
  std::vector<Vec2> found;
  for (std::size_t i = 0; i < obstacle_count_; ++i) {
    const Rect& r = rects_[i];
    const Vec2 corners[4] = {
        {r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}};
    for (const Vec2& c : corners) {
      const bool ne = quadrant_occupied(c, 1, 1, -1), sw = quadrant_occupied(c, -1, -1, -1);
      const bool nw = quadrant_occupied(c, -1, 1, -1), se = quadrant_occupied(c, 1, -1, -1);
      if ((ne && sw && !nw && !se) || (nw && se && !ne && !sw)) found.push_back(c);
    }
  }
  std::sort(found.begin(), found.end(),
            [](Vec2 a, Vec2 b) { return std::tie(a.x, a.y) < std::tie(b.x, b.y); });
  found.erase(std::unique(found.begin(), found.end()), found.end());
  pinches_ = std::move(found);
  for (std::size_t k = 0; k < pinches_.size(); ++k)
    cells_[static_cast<std::size_t>(cell_y(pinches_[k].y)) * nx_ + cell_x(pinches_[k].x)]
        .pinches.push_back(static_cast<std::int32_t>(k));
}

bool ObstacleMap::is_pinch_point(Vec2 c) const {
  return std::binary_search(pinches_.begin(), pinches_.end(), c,
                            [](Vec2 a, Vec2 b) { return std::tie(a.x, a.y) < std::tie(b.x, b.y); });
}

bool ObstacleMap::sandwiched(Vec2 p, Vec2 q) const {
  // Only an axis-parallel segment can run between two rectangles along a shared edge.
  const bool horizontal = p.y == q.y, vertical = p.x == q.x;
  if (horizontal == vertical) return false;
  const double line = horizontal ? p.y : p.x;
  const double lo = horizontal ? std::min(p.x, q.x) : std::min(p.y, q.y);
  const double hi = horizontal ? std::max(p.x, q.x) : std::max(p.y, q.y);
  struct Span {
    double a, b;
  };
  std::vector<Span> below, above;  // rectangles whose edge lies on the line, by side
  walk_cells(p, q, [&](const Cell& c) {
    for (std::int32_t i : c.rects) {
      const Rect& r = rects_[i];
      const double emin = horizontal ? r.xmin : r.ymin, emax = horizontal ? r.xmax : r.ymax;
      const double a = std::max(emin, lo), b = std::min(emax, hi);
      if (!(a < b)) continue;
      if ((horizontal ? r.ymax : r.xmax) == line) below.push_back({a, b});
      if ((horizontal ? r.ymin : r.xmin) == line) above.push_back({a, b});
    }
    return true;
  });
  for (const Span& s : below)
    for (const Span& t : above)
      if (std::max(s.a, t.a) < std::min(s.b, t.b)) return true;
  return false;
}

bool ObstacleMap::segment_free(Vec2 p, Vec2 q) const {
  bool blocked = false;
  walk_cells(p, q, [&](const Cell& c) {
    for (std::int32_t i : c.rects)
      if (geom::segment_enters_open_rect(p, q, rects_[i])) {
        blocked = true;
        return false;
      }
    for (std::int32_t k : c.pinches)
      if (!(p == q) && geom::in_segment_interior(p, q, pinches_[k])) {
        blocked = true;
        return false;
      }
    return true;
  });
  return !blocked && !sandwiched(p, q);
}

bool ObstacleMap::point_free(Vec2 p) const {
  if (!geom::in_closed_rect(free_floor_, p)) return false;
  for (std::int32_t i : cell(cell_x(p.x), cell_y(p.y)).rects)
    if (geom::in_open_rect(rects_[i], p)) return false;
  return true;
}

}  // namespace plantsim::planner
