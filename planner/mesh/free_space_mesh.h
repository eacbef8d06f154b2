// The free floor cut into rectangles (a vertical decomposition of the plane minus the union of
// the inflated obstacles), with the vertical "portals" where two cells meet. A sweep in x keeps
// the floor's free y-intervals; a cell lives while its interval does not change. Cells'
// bottom and top edges are always obstacle or floor, so paths pass between cells only through
// portals, and two cells meeting at a single point (a pinch) or along a zero-width slit share
// none: the ObstacleMap's rules of passage, by construction.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/vec2.h"
#include "planner/mesh/box_buckets.h"

namespace plantsim::planner {

using geom::Rect;
using geom::Vec2;

struct MeshCell {
  double xlo, xhi, ylo, yhi;
};

/// A vertical segment x, [y0, y1] (y0 < y1) shared by cell `left` (which ends at x) and cell
/// `right` (which starts at x). An end is a corner when the obstacle union turns there (one
/// quadrant around it is blocked): only there can a shortest path bend.
struct MeshPortal {
  double x, y0, y1;
  std::int32_t left, right;
  bool corner0, corner1;  ///< the bottom (y0) and top (y1) end
};

class FreeSpaceMesh {
 public:
  /// `blocked`: the inflated obstacles (any part outside `free_floor` is ignored).
  FreeSpaceMesh(const std::vector<Rect>& blocked, const Rect& free_floor);

  const std::vector<MeshCell>& cells() const { return cells_; }
  const std::vector<MeshPortal>& portals() const { return portals_; }
  /// A cell's portals on its left (x = xlo) or right (x = xhi) side, ordered by y.
  struct Span {
    const std::int32_t* b;
    const std::int32_t* e;
    const std::int32_t* begin() const { return b; }
    const std::int32_t* end() const { return e; }
  };
  Span left_portals(std::int32_t cell) const { return span(left_index_, left_start_, cell); }
  Span right_portals(std::int32_t cell) const { return span(right_index_, right_start_, cell); }
  std::int32_t portal_count(std::int32_t cell) const {
    return left_start_[cell + 1] - left_start_[cell] + right_start_[cell + 1] - right_start_[cell];
  }
  /// Every cell whose closed rectangle holds p (within the mesh's tolerance): two or more when
  /// p lies on a portal or a shared corner, none when p is not on the free floor.
  std::vector<std::int32_t> cells_at(Vec2 p) const;
  bool cell_holds(std::int32_t cell, Vec2 p) const;
  /// p is where two blocked quadrants touch diagonally (a pinch): the free floor on the two
  /// other sides meets there, but no path passes from one to the other.
  bool is_pinch(Vec2 p) const;
  /// Absolute tolerance for comparing computed coordinates (an interval's ends projected across
  /// a cell): a few hundred ulps of the floor's extent, far below the inflation lattice, so
  /// cells one lattice step wide stay apart.
  double tolerance() const { return eps_; }

 private:
  static Span span(const std::vector<std::int32_t>& index, const std::vector<std::int32_t>& start,
                   std::int32_t cell) {
    return {index.data() + start[cell], index.data() + start[cell + 1]};
  }
  void index_portals();
  void index_cells();

  std::vector<MeshCell> cells_;
  std::vector<MeshPortal> portals_;
  std::vector<std::int32_t> left_index_, left_start_, right_index_, right_start_;
  BoxBuckets buckets_;  // point location
  double eps_ = 1e-13;
};

}  // namespace plantsim::planner
