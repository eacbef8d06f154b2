// Seed 004's work area as a grid of square cells (the document: a 40 x 20 m area in 2 x 2 m
// cells), its rectangular decomposition into sub-regions, the back-and-forth sweep inside a
// sub-region, and breadth-first travel between cells. A cell is blocked when an obstacle (grown
// by whatever part of the robot's clearance the half cell does not already give) reaches into
// it or it sticks out of the floor; the robot moves between 4-neighbouring cell centres.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::planner {

struct Cell {
  int column = 0;
  int row = 0;
  friend bool operator==(Cell, Cell) = default;
};

/// The 4-neighbour of c in heading h (0 east, 1 north, 2 west, 3 south).
inline Cell neighbour(Cell c, int h) {
  static constexpr int dc[4] = {1, 0, -1, 0}, dr[4] = {0, 1, 0, -1};
  return {c.column + dc[h], c.row + dr[h]};
}
/// The heading from c to its 4-neighbour n.
inline int heading_between(Cell c, Cell n) {
  return n.column > c.column ? 0 : n.row > c.row ? 1 : n.column < c.column ? 2 : 3;
}
/// Changes of heading along a 4-connected cell path (turning back counts two).
int turns_along(const std::vector<Cell>& path);

/// A sub-region: cells [column, column + width) x [row, row + height).
struct CellRect {
  int column = 0, row = 0, width = 0, height = 0;
  bool contains(Cell c) const {
    return c.column >= column && c.column < column + width && c.row >= row && c.row < row + height;
  }
  int cells() const { return width * height; }
};

class CoverageGrid {
 public:
  CoverageGrid(geom::Rect floor, double cell_m, const std::vector<geom::Rect>& obstacles,
               double clearance_m);
  /// From a pattern, bottom row last ('#' blocked, anything else free): for tests.
  static CoverageGrid from_rows(const std::vector<std::string>& rows, double cell_m = 2.0);

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  double cell_m() const { return cell_m_; }
  bool free(Cell c) const { return inside(c) && !blocked_[index(c)]; }
  bool inside(Cell c) const {
    return c.column >= 0 && c.row >= 0 && c.column < columns_ && c.row < rows_;
  }
  std::size_t index(Cell c) const { return static_cast<std::size_t>(c.row) * columns_ + c.column; }
  geom::Vec2 centre(Cell c) const;
  /// The free cell whose centre is nearest p, if any.
  std::optional<Cell> nearest_free(geom::Vec2 p) const;
  geom::Rect cell_rect(Cell c) const;
  /// The cell containing p, if p is on the grid.
  std::optional<Cell> cell_at(geom::Vec2 p) const;

  /// Free cells reachable from `from` (4-connected).
  std::vector<bool> reachable(Cell from) const;
  /// Shortest 4-connected cell path from -> to (both included), empty if none.
  std::vector<Cell> travel(Cell from, Cell to) const;
  /// Breadth-first distances (in cells) from every cell of `sources`; -1 where unreachable.
  std::vector<int> distances_from(const std::vector<Cell>& sources) const;
  /// Downhill in `dist` from `from` to a cell at distance 0, keeping the heading where it can
  /// (fewer turns for the same length), starting with `heading` (-1: none yet); empty if `from`
  /// is unreachable.
  std::vector<Cell> descend(const std::vector<int>& dist, Cell from, int heading = -1) const;

  /// The rectangular decomposition: scanning rows bottom to top and cells left to right, each
  /// free cell not yet assigned starts a sub-region that grows right as far as it can, then up
  /// while the whole span stays free: the work area cut by vertical and horizontal lines.
  /// Only cells in `within` (e.g. those reachable) are used.
  std::vector<CellRect> decompose(const std::vector<bool>& within) const;

 private:
  CoverageGrid() = default;
  geom::Vec2 origin_;
  double cell_m_ = 1.0;
  int columns_ = 0, rows_ = 0;
  std::vector<std::uint8_t> blocked_;
};

/// The back-and-forth sweep of a sub-region from one of its corners (0: bottom-left,
/// 1: bottom-right, 2: top-left, 3: top-right), lanes along x or along y.
std::vector<Cell> sweep(const CellRect& r, int corner, bool lanes_along_x);

}  // namespace plantsim::planner
