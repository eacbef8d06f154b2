// The free floor as convex polygons, the mesh Polyanya searches (Cui, Harabor and Grastien,
// IJCAI 2017): the walls of the rectangle mesh triangulated (a constrained Delaunay
// triangulation, CGAL's) and the free triangles merged greedily while the union stays convex.
// Where the rectangle mesh cuts an open area at every step of a staircase wall, one polygon
// here spans it, so a path crosses far fewer edges. Walls (obstacle sides, the floor's edge,
// zero-width slits) are polygon edges with no neighbour; two polygons meeting at a single point
// (a pinch) share no edge, so paths pass where the rectangle mesh lets them and nowhere else.
#pragma once

#include <cstdint>
#include <vector>

#include "planner/mesh/box_buckets.h"
#include "planner/mesh/free_space_mesh.h"

namespace plantsim::planner {

class ConvexMesh {
 public:
  /// The most corners a merged polygon may have. Without a bound, a wall of many small
  /// obstacles in a row (a comb: brackets along a tunnel) makes one polygon of thousands of
  /// collinear corners: merging it is quadratic (8,000 rectangles: 104 s, 1.1 GB) and every
  /// search step into it walks all its edges. At 32 the benchmark maps' polygons stay as they
  /// were (BigGameHunters' largest has 47 corners; its search expands 0.1 % more nodes).
  static constexpr int kMaxCorners = 32;

  /// The same free floor as `rectangles`, cut into convex polygons.
  explicit ConvexMesh(const FreeSpaceMesh& rectangles);

  std::int32_t polygon_count() const { return static_cast<std::int32_t>(first_.size()) - 1; }
  std::int32_t size(std::int32_t polygon) const { return first_[polygon + 1] - first_[polygon]; }
  /// The polygon's k-th corner (counter-clockwise; -n <= k < 2n, taken modulo n), a vertex index.
  std::int32_t vertex(std::int32_t polygon, std::int32_t k) const {
    return corner_[first_[polygon] + wrap(polygon, k)];
  }
  /// The polygon beyond edge k (from corner k to corner k + 1), -1 for a wall.
  std::int32_t neighbour(std::int32_t polygon, std::int32_t k) const {
    return neighbour_[first_[polygon] + wrap(polygon, k)];
  }
  /// The same edge's index in the neighbour (where it runs from corner k + 1 to corner k).
  std::int32_t twin(std::int32_t polygon, std::int32_t k) const {
    return twin_[first_[polygon] + wrap(polygon, k)];
  }
  /// The same three as arrays over the polygon's corners (index k in [0, size)), for loops
  /// that walk a polygon.
  const std::int32_t* corners(std::int32_t polygon) const {
    return corner_.data() + first_[polygon];
  }
  const std::int32_t* neighbours(std::int32_t polygon) const {
    return neighbour_.data() + first_[polygon];
  }
  const std::int32_t* twins(std::int32_t polygon) const { return twin_.data() + first_[polygon]; }
  /// The polygon's corners' coordinates, in the same order (points()[corners(polygon)[k]],
  /// stored beside each other: the search reads a polygon's corners in a row).
  const Vec2* corner_points(std::int32_t polygon) const {
    return corner_point_.data() + first_[polygon];
  }
  /// Edges with a polygon on both sides, each counted once.
  std::int64_t portal_count() const { return portals_; }
  const std::vector<Vec2>& points() const { return points_; }
  /// A vertex a shortest path may bend at: an obstacle's convex corner or a slit's tip (a wedge
  /// of free floor wider than a half-turn between two walls).
  bool is_corner(std::int32_t vertex) const { return corner_flag_[vertex] != 0; }
  /// A vertex where free wedges meet that a path may not pass between (walls touching at a
  /// point): how far it is depends on the side it is reached from.
  bool is_pinch(std::int32_t vertex) const { return pinch_flag_[vertex] != 0; }
  /// Every polygon whose closed area holds p (within the tolerance): two or more on a shared
  /// edge or vertex, none off the free floor.
  std::vector<std::int32_t> polygons_at(Vec2 p) const;
  bool polygon_holds(std::int32_t polygon, Vec2 p) const;
  double tolerance() const { return eps_; }
  struct Piece;  ///< a polygon while the mesh is built (convex_mesh.cpp)

 private:
  // k within one turn either way of [0, n): no division on the search's hot path.
  std::int32_t wrap(std::int32_t polygon, std::int32_t k) const {
    const std::int32_t n = size(polygon);
    return k >= n ? k - n : k < 0 ? k + n : k;
  }
  void lay_out(const std::vector<Piece>& pieces, const std::vector<std::int32_t>& owner);
  void mark_corners();
  void index_polygons();

  std::vector<Vec2> points_;
  std::vector<std::uint8_t> corner_flag_,
      pinch_flag_;                   // not vector<bool>: read on every search step
  std::vector<std::int32_t> first_;  // polygon p's corners are corner_[first_[p] .. first_[p + 1])
  std::vector<std::int32_t> corner_, neighbour_, twin_;
  std::vector<Vec2> corner_point_;
  std::int64_t portals_ = 0;
  BoxBuckets buckets_;  // point location
  double eps_ = 1e-13;
};

}  // namespace plantsim::planner
