// The planner's view of obstacles: rectangles already inflated for the robot, the floor
// boundary as four wall rectangles, a uniform grid for locality, the points where obstacles
// touch only at a corner ("pinch points"), and the exact question "may a path use segment
// [p, q]?". Free space is the plane minus the union of the closed rectangles, except that a
// path may touch and slide along the union's boundary. A segment is refused when it enters
// an open rectangle, passes through a pinch point, or slides between two rectangles that
// share an edge (the union's interior, which no single rectangle's interior contains).
#pragma once

#include <algorithm>
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
  const std::vector<Vec2>& pinch_points() const { return pinches_; }  ///< sorted by (x, y)
  bool is_pinch_point(Vec2 c) const;
  const Rect& free_floor() const { return free_floor_; }

  /// True when rectangles other than `self` fill the open quadrant (sx, sy) at c.
  bool quadrant_occupied(Vec2 c, int sx, int sy, std::int32_t self) const;

  // The uniform grid, for searches that work outward from a point.
  int grid_width() const { return nx_; }
  int grid_height() const { return ny_; }
  double cell_size() const { return cell_size_; }
  int cell_x(double x) const;
  int cell_y(double y) const;
  Rect cell_bounds(int cx, int cy) const {
    return {x0_ + cx * cell_size_, y0_ + cy * cell_size_, x0_ + (cx + 1) * cell_size_,
            y0_ + (cy + 1) * cell_size_};
  }
  const std::vector<std::int32_t>& rects_in_cell(int cx, int cy) const {
    return cell(cx, cy).rects;
  }

 private:
  struct Cell {
    std::vector<std::int32_t> rects;
    std::vector<std::int32_t> pinches;
  };
  const Cell& cell(int cx, int cy) const { return cells_[static_cast<std::size_t>(cy) * nx_ + cx]; }
  /// Visits the cells around the closed segment, starting at p's end, until f returns false.
  /// Conservative: every cell a rectangle touching the segment is registered in is visited
  /// (rows are padded by one cell so that rounding in the line's y can never drop one).
  template <typename F>
  void walk_cells(Vec2 p, Vec2 q, F&& f) const;
  bool sandwiched(Vec2 p, Vec2 q) const;
  void find_pinch_points();

  std::vector<Rect> rects_;
  std::size_t obstacle_count_ = 0;
  Rect free_floor_;
  std::vector<Vec2> pinches_;
  // Uniform grid over the free floor.
  double x0_ = 0, y0_ = 0, cell_size_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<Cell> cells_;
};

template <typename F>
void ObstacleMap::walk_cells(Vec2 p, Vec2 q, F&& f) const {
  const int c0 = cell_x(p.x), c1 = cell_x(q.x);
  const int step = c1 >= c0 ? 1 : -1;
  const double dx = q.x - p.x;
  for (int cx = c0;; cx += step) {
    double ya = p.y, yb = q.y;
    if (c0 != c1 && dx != 0) {
      const Rect b = cell_bounds(cx, 0);
      const double xa = std::clamp(b.xmin, std::min(p.x, q.x), std::max(p.x, q.x));
      const double xb = std::clamp(b.xmax, std::min(p.x, q.x), std::max(p.x, q.x));
      ya = p.y + (q.y - p.y) * ((xa - p.x) / dx);
      yb = p.y + (q.y - p.y) * ((xb - p.x) / dx);
    }
    const int r0 = std::max(cell_y(std::min(ya, yb)) - 1, 0);
    const int r1 = std::min(cell_y(std::max(ya, yb)) + 1, ny_ - 1);
    // Rows in the direction of travel, so a blocker near p is met first.
    if (q.y >= p.y) {
      for (int cy = r0; cy <= r1; ++cy)
        if (!f(cell(cx, cy))) return;
    } else {
      for (int cy = r1; cy >= r0; --cy)
        if (!f(cell(cx, cy))) return;
    }
    if (cx == c1) return;
  }
}

}  // namespace plantsim::planner
