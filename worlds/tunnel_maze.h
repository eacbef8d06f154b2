// A cable-tunnel maze (seed 003) as a lattice: junction nodes on a square grid, corridors of a
// set width along the open edges between neighbouring nodes, solid rock everywhere else. The
// world's floor and obstacle rectangles are derived from it; planners that reason about
// junctions (the hand rules) read the lattice itself.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::worlds {

/// Headings on the lattice, counter-clockwise from east.
enum class Heading : int { kEast = 0, kNorth = 1, kWest = 2, kSouth = 3 };

struct LatticeNode {
  int column = 0;
  int row = 0;
  friend bool operator==(LatticeNode, LatticeNode) = default;
};

class TunnelMaze {
 public:
  TunnelMaze() = default;
  TunnelMaze(geom::Vec2 origin, double pitch_m, double corridor_m, int columns, int rows);

  /// Opens every edge along a straight run between two nodes in the same row or column.
  /// Throws std::invalid_argument when they are not aligned or outside the lattice.
  void open_run(LatticeNode a, LatticeNode b);

  bool open(LatticeNode n, Heading h) const;
  int degree(LatticeNode n) const;  ///< open corridors at a node
  bool inside(LatticeNode n) const {
    return n.column >= 0 && n.row >= 0 && n.column < columns_ && n.row < rows_;
  }
  static LatticeNode step(LatticeNode n, Heading h);

  geom::Vec2 position(LatticeNode n) const;
  /// The node on a corridor nearest to p (only nodes with an open corridor count).
  std::optional<LatticeNode> nearest_node(geom::Vec2 p) const;

  /// The floor (the lattice plus half a pitch around it) and the solid rock as rectangles.
  geom::Rect floor() const;
  std::vector<geom::Rect> rock() const;

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  double pitch_m() const { return pitch_m_; }
  double corridor_m() const { return corridor_m_; }
  int open_edges() const;

 private:
  std::size_t index(LatticeNode n) const {
    return static_cast<std::size_t>(n.row) * columns_ + n.column;
  }
  geom::Vec2 origin_;
  double pitch_m_ = 2.0;
  double corridor_m_ = 1.0;
  int columns_ = 0;
  int rows_ = 0;
  std::vector<std::uint8_t>
      open_;  // per node, bit h set when the corridor towards heading h is open
};

}  // namespace plantsim::worlds
