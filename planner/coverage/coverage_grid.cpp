// Cells, the decomposition, sweeps and breadth-first travel.
#include "planner/coverage/coverage_grid.h"

#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>

#include "geometry/predicates.h"

namespace plantsim::planner {
CoverageGrid::CoverageGrid(geom::Rect floor, double cell_m,
                           const std::vector<geom::Rect>& obstacles, double clearance_m)
    : origin_{floor.xmin, floor.ymin}, cell_m_(cell_m) {
  if (!(cell_m > 0)) throw std::invalid_argument("coverage cell size must be positive");
  columns_ = static_cast<int>(std::floor(floor.width() / cell_m + 1e-9));
  rows_ = static_cast<int>(std::floor(floor.height() / cell_m + 1e-9));
  if (columns_ < 1 || rows_ < 1)
    throw std::invalid_argument("the floor is smaller than one coverage cell");
  if (static_cast<double>(columns_) * rows_ > 4e6)
    throw std::invalid_argument("more than 4 million coverage cells");
  blocked_.assign(static_cast<std::size_t>(columns_) * rows_, 0);
  // The robot stands at cell centres and moves along the lines joining them: half a cell of
  // clearance comes free, the rest of the robot's clearance grows the obstacles.
  const double grow = std::max(0.0, clearance_m - 0.5 * cell_m);
  for (const geom::Rect& o : obstacles) {
    const geom::Rect g = o.inflated(grow);
    const int c0 = std::max(0, static_cast<int>(std::floor((g.xmin - origin_.x) / cell_m)));
    const int c1 =
        std::min(columns_ - 1, static_cast<int>(std::floor((g.xmax - origin_.x) / cell_m)));
    const int r0 = std::max(0, static_cast<int>(std::floor((g.ymin - origin_.y) / cell_m)));
    const int r1 = std::min(rows_ - 1, static_cast<int>(std::floor((g.ymax - origin_.y) / cell_m)));
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c)
        if (geom::rects_overlap_open(g, cell_rect({c, r}))) blocked_[index({c, r})] = 1;
  }
  // The floor's own walls: a clearance larger than half a cell blocks the outer ring.
  if (grow > 0)
    for (int r = 0; r < rows_; ++r)
      for (int c = 0; c < columns_; ++c)
        if (c == 0 || r == 0 || c == columns_ - 1 || r == rows_ - 1) blocked_[index({c, r})] = 1;
}

CoverageGrid CoverageGrid::from_rows(const std::vector<std::string>& rows, double cell_m) {
  CoverageGrid g;
  g.cell_m_ = cell_m;
  g.rows_ = static_cast<int>(rows.size());
  g.columns_ = rows.empty() ? 0 : static_cast<int>(rows[0].size());
  g.blocked_.assign(static_cast<std::size_t>(g.columns_) * g.rows_, 0);
  for (int r = 0; r < g.rows_; ++r)
    for (int c = 0; c < g.columns_; ++c)
      g.blocked_[g.index({c, r})] = rows[g.rows_ - 1 - r][c] == '#';
  return g;
}

geom::Vec2 CoverageGrid::centre(Cell c) const {
  return {origin_.x + (c.column + 0.5) * cell_m_, origin_.y + (c.row + 0.5) * cell_m_};
}

geom::Rect CoverageGrid::cell_rect(Cell c) const {
  return {origin_.x + c.column * cell_m_, origin_.y + c.row * cell_m_,
          origin_.x + (c.column + 1) * cell_m_, origin_.y + (c.row + 1) * cell_m_};
}

std::optional<Cell> CoverageGrid::cell_at(geom::Vec2 p) const {
  const Cell c{static_cast<int>(std::floor((p.x - origin_.x) / cell_m_)),
               static_cast<int>(std::floor((p.y - origin_.y) / cell_m_))};
  if (!inside(c)) return std::nullopt;
  return c;
}

std::optional<Cell> CoverageGrid::nearest_free(geom::Vec2 p) const {
  std::optional<Cell> best;
  double best_d = INFINITY;
  for (int r = 0; r < rows_; ++r)
    for (int c = 0; c < columns_; ++c)
      if (free({c, r})) {
        const double d = geom::distance(p, centre({c, r}));
        if (d < best_d) best_d = d, best = Cell{c, r};
      }
  return best;
}

std::vector<int> CoverageGrid::distances_from(const std::vector<Cell>& sources) const {
  std::vector<int> dist(blocked_.size(), -1);
  std::deque<Cell> queue;
  for (Cell s : sources)
    if (free(s) && dist[index(s)] < 0) dist[index(s)] = 0, queue.push_back(s);
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    for (int h = 0; h < 4; ++h) {
      const Cell n = neighbour(c, h);
      if (free(n) && dist[index(n)] < 0) dist[index(n)] = dist[index(c)] + 1, queue.push_back(n);
    }
  }
  return dist;
}

std::vector<bool> CoverageGrid::reachable(Cell from) const {
  const std::vector<int> d = distances_from({from});
  std::vector<bool> out(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) out[i] = d[i] >= 0;
  return out;
}

std::vector<Cell> CoverageGrid::travel(Cell from, Cell to) const {
  return descend(distances_from({to}), from);
}

std::vector<Cell> CoverageGrid::descend(const std::vector<int>& dist, Cell from,
                                        int heading) const {
  if (!free(from) || dist[index(from)] < 0) return {};
  std::vector<Cell> path{from};
  while (dist[index(path.back())] > 0) {
    const Cell c = path.back();
    for (int k = 0; k < 4; ++k) {
      const int h = heading < 0 ? k : (heading + k) % 4;  // current heading first
      const Cell n = neighbour(c, h);
      if (free(n) && dist[index(n)] == dist[index(c)] - 1) {
        heading = h;
        path.push_back(n);
        break;
      }
    }
  }
  return path;
}

int turns_along(const std::vector<Cell>& path) {
  int turns = 0;
  for (std::size_t i = 2; i < path.size(); ++i) {
    const int turn =
        (heading_between(path[i - 1], path[i]) - heading_between(path[i - 2], path[i - 1]) + 4) % 4;
    turns += turn == 2 ? 2 : turn != 0;
  }
  return turns;
}

std::vector<CellRect> CoverageGrid::decompose(const std::vector<bool>& within) const {
  std::vector<bool> taken(blocked_.size(), false);
  auto usable = [&](Cell c) { return free(c) && within[index(c)] && !taken[index(c)]; };
  std::vector<CellRect> out;
  for (int r = 0; r < rows_; ++r)
    for (int c = 0; c < columns_; ++c) {
      if (!usable({c, r})) continue;
      CellRect rect{c, r, 1, 1};
      while (usable({c + rect.width, r})) ++rect.width;
      for (bool more = true; more;) {
        for (int k = 0; k < rect.width && more; ++k) more = usable({c + k, r + rect.height});
        if (more) ++rect.height;
      }
      for (int y = r; y < r + rect.height; ++y)
        for (int x = c; x < c + rect.width; ++x) taken[index({x, y})] = true;
      out.push_back(rect);
    }
  return out;
}

std::vector<Cell> sweep(const CellRect& r, int corner, bool lanes_along_x) {
  const bool from_right = corner == 1 || corner == 3, from_top = corner == 2 || corner == 3;
  std::vector<Cell> out;
  out.reserve(static_cast<std::size_t>(r.cells()));
  if (lanes_along_x) {  // stepping in y
    for (int k = 0; k < r.height; ++k) {
      const int row = from_top ? r.row + r.height - 1 - k : r.row + k;
      const bool rightwards = (k % 2 == 0) != from_right;
      for (int j = 0; j < r.width; ++j)
        out.push_back({rightwards ? r.column + j : r.column + r.width - 1 - j, row});
    }
  } else {  // stepping in x
    for (int k = 0; k < r.width; ++k) {
      const int column = from_right ? r.column + r.width - 1 - k : r.column + k;
      const bool upwards = (k % 2 == 0) != from_top;
      for (int j = 0; j < r.height; ++j)
        out.push_back({column, upwards ? r.row + j : r.row + r.height - 1 - j});
    }
  }
  return out;
}

}  // namespace plantsim::planner
