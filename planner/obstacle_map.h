// The planner's view of obstacles: rectangles already inflated for the robot, the floor
// boundary as four wall rectangles, a uniform grid for locality, the points where obstacles
// touch only at a corner ("pinch points"), and the exact question "may a path use segment
// [p, q]?". Free space is the plane minus the union of the closed rectangles, except that a
// path may touch and slide along the union's boundary. A segment is refused when it enters
// an open rectangle, passes through a pinch point, or slides between two rectangles that
// share an edge (the union's interior, which no single rectangle's interior contains).
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::planner {

using geom::Rect;
using geom::Vec2;

class ObstacleMap {
 public:
  /// `inflated` are obstacle rectangles already grown by the robot's clearance; the walls
  /// are placed so that the free floor is `floor` shrunk by `wall_inflation`.
  ObstacleMap(std::vector<Rect> inflated, const Rect& floor, double wall_inflation);

  bool segment_free(Vec2 p, Vec2 q) const;
  /// Not inside any open rectangle, and on the floor.
  bool point_free(Vec2 p) const;

  const std::vector<Rect>& rects() const { return rects_; }  ///< obstacles then walls
  std::size_t obstacle_count() const { return obstacle_count_; }
  const std::vector<Vec2>& pinch_points() const { return pinches_; }
  const Rect& free_floor() const { return free_floor_; }

  /// Calls f(rect_index) for rectangles registered in grid cells around the closed segment
  /// (a rectangle may be reported more than once). Conservative: never misses one that
  /// touches the segment.
  template <typename F>
  void for_rects_near_segment(Vec2 p, Vec2 q, F&& f) const;

  /// True when rectangles other than `self` fill the open quadrant (sx, sy) at c.
  bool quadrant_occupied(Vec2 c, int sx, int sy, std::int32_t self) const;

 private:
  struct Cell {
    std::vector<std::int32_t> rects;
    std::vector<std::int32_t> pinches;
  };
  int cell_x(double x) const;
  int cell_y(double y) const;
  const Cell& cell(int cx, int cy) const { return cells_[static_cast<std::size_t>(cy) * nx_ + cx]; }
  template <typename F>
  void for_cells_near_segment(Vec2 p, Vec2 q, F&& f) const;
  bool sandwiched(Vec2 p, Vec2 q) const;
  void find_pinch_points();

  std::vector<Rect> rects_;
  std::size_t obstacle_count_ = 0;
  Rect free_floor_;
  std::vector<Vec2> pinches_;
  // Uniform grid over the walls' inner region.
  double x0_ = 0, y0_ = 0, cell_size_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<Cell> cells_;
};

template <typename F>
void ObstacleMap::for_cells_near_segment(Vec2 p, Vec2 q, F&& f) const {
  // Walk the columns the segment spans; in each, the rows its y-range covers, padded by one
  // cell on each side so that rounding in the line's y can never drop a cell.
  if (p.x > q.x) std::swap(p, q);
  const int c0 = cell_x(p.x), c1 = cell_x(q.x);
  const double dx = q.x - p.x;
  for (int cx = c0; cx <= c1; ++cx) {
    double ya, yb;
    if (c0 == c1 || dx == 0) {
      ya = p.y;
      yb = q.y;
    } else {
      const double xa = std::max(p.x, x0_ + cx * cell_size_);
      const double xb = std::min(q.x, x0_ + (cx + 1) * cell_size_);
      ya = p.y + (q.y - p.y) * ((xa - p.x) / dx);
      yb = p.y + (q.y - p.y) * ((xb - p.x) / dx);
    }
    int r0 = cell_y(std::min(ya, yb)) - 1, r1 = cell_y(std::max(ya, yb)) + 1;
    r0 = std::max(r0, 0);
    r1 = std::min(r1, ny_ - 1);
    for (int cy = r0; cy <= r1; ++cy) f(cell(cx, cy));
  }
}

template <typename F>
void ObstacleMap::for_rects_near_segment(Vec2 p, Vec2 q, F&& f) const {
  for_cells_near_segment(p, q, [&](const Cell& c) {
    for (std::int32_t i : c.rects) f(i);
  });
}

}  // namespace plantsim::planner
