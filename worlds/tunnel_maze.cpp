// The lattice, its corridors and the rock between them.
#include "worlds/tunnel_maze.h"

#include <cmath>
#include <stdexcept>

namespace plantsim::worlds {

TunnelMaze::TunnelMaze(geom::Vec2 origin, double pitch_m, double corridor_m, int columns, int rows)
    : origin_(origin),
      pitch_m_(pitch_m),
      corridor_m_(corridor_m),
      columns_(columns),
      rows_(rows),
      open_(static_cast<std::size_t>(columns) * rows, 0) {
  if (!(pitch_m > 0) || !(corridor_m > 0) || corridor_m >= pitch_m)
    throw std::invalid_argument("corridor width must be positive and less than the pitch");
  if (columns < 1 || rows < 1 || columns > 1000 || rows > 1000)
    throw std::invalid_argument("1 to 1000 columns and rows");
}

LatticeNode TunnelMaze::step(LatticeNode n, Heading h) {
  static constexpr int dc[4] = {1, 0, -1, 0}, dr[4] = {0, 1, 0, -1};
  return {n.column + dc[static_cast<int>(h)], n.row + dr[static_cast<int>(h)]};
}

void TunnelMaze::open_run(LatticeNode a, LatticeNode b) {
  if (!inside(a) || !inside(b)) throw std::invalid_argument("corridor end outside the lattice");
  if (a.column != b.column && a.row != b.row)
    throw std::invalid_argument("corridor ends not in one row or column");
  if (a == b) throw std::invalid_argument("corridor of zero length");
  const Heading h = a.row == b.row ? (b.column > a.column ? Heading::kEast : Heading::kWest)
                                   : (b.row > a.row ? Heading::kNorth : Heading::kSouth);
  const Heading back = static_cast<Heading>((static_cast<int>(h) + 2) % 4);
  for (LatticeNode n = a; !(n == b); n = step(n, h)) {
    open_[index(n)] |= 1u << static_cast<int>(h);
    open_[index(step(n, h))] |= 1u << static_cast<int>(back);
  }
}

bool TunnelMaze::open(LatticeNode n, Heading h) const {
  return inside(n) && (open_[index(n)] >> static_cast<int>(h) & 1u);
}

int TunnelMaze::degree(LatticeNode n) const {
  int d = 0;
  for (int h = 0; h < 4; ++h) d += open(n, static_cast<Heading>(h));
  return d;
}

int TunnelMaze::open_edges() const {
  int twice = 0;
  for (int r = 0; r < rows_; ++r)
    for (int c = 0; c < columns_; ++c) twice += degree({c, r});
  return twice / 2;
}

geom::Vec2 TunnelMaze::position(LatticeNode n) const {
  return {origin_.x + pitch_m_ * n.column, origin_.y + pitch_m_ * n.row};
}

std::optional<LatticeNode> TunnelMaze::nearest_node(geom::Vec2 p) const {
  std::optional<LatticeNode> best;
  double best_d = INFINITY;
  for (int r = 0; r < rows_; ++r)
    for (int c = 0; c < columns_; ++c)
      if (degree({c, r}) > 0) {
        const double d = geom::distance(p, position({c, r}));
        if (d < best_d) best_d = d, best = LatticeNode{c, r};
      }
  return best;
}

geom::Rect TunnelMaze::floor() const {
  const double half = 0.5 * pitch_m_;
  return {origin_.x - half, origin_.y - half, origin_.x + pitch_m_ * (columns_ - 1) + half,
          origin_.y + pitch_m_ * (rows_ - 1) + half};
}

std::vector<geom::Rect> TunnelMaze::rock() const {
  // Each axis splits into bands: corridor bands centred on the lattice lines, gap bands between
  // them, and the margins to the floor's edge. A band pair is rock unless it is a node with a
  // corridor or an open edge; rock runs along a row are merged into one rectangle.
  struct Band {
    double lo, hi;
    int line;  // lattice index of a corridor band, or -1
    int gap;   // index of the gap after lattice line `gap`, or -1
  };
  auto bands = [&](double origin, int count) {
    std::vector<Band> out;
    const double w = 0.5 * corridor_m_, half = 0.5 * pitch_m_;
    out.push_back({origin - half, origin - w, -1, -1});
    for (int i = 0; i < count; ++i) {
      const double x = origin + pitch_m_ * i;
      out.push_back({x - w, x + w, i, -1});
      if (i + 1 < count) out.push_back({x + w, x + pitch_m_ - w, -1, i});
    }
    out.push_back(
        {origin + pitch_m_ * (count - 1) + w, origin + pitch_m_ * (count - 1) + half, -1, -1});
    return out;
  };
  const std::vector<Band> xs = bands(origin_.x, columns_), ys = bands(origin_.y, rows_);
  auto free_cell = [&](const Band& bx, const Band& by) {
    if (bx.line >= 0 && by.line >= 0) return degree({bx.line, by.line}) > 0;
    if (bx.gap >= 0 && by.line >= 0) return open({bx.gap, by.line}, Heading::kEast);
    if (bx.line >= 0 && by.gap >= 0) return open({bx.line, by.gap}, Heading::kNorth);
    return false;
  };
  std::vector<geom::Rect> out;
  for (const Band& by : ys) {
    std::size_t i = 0;
    while (i < xs.size()) {
      if (free_cell(xs[i], by)) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j + 1 < xs.size() && !free_cell(xs[j + 1], by)) ++j;
      out.push_back({xs[i].lo, by.lo, xs[j].hi, by.hi});
      i = j + 1;
    }
  }
  return out;
}

}  // namespace plantsim::worlds
