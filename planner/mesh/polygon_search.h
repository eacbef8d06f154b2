// Exact any-angle shortest paths by interval search over the convex mesh: Polyanya (Cui,
// Harabor and Grastien, IJCAI 2017) as its authors wrote it, on polygons with edges at any
// angle. A search node is an interval of a polygon edge every point of which the node's root
// sees, and the polygon it opens into; expanding it casts the two rays from the root through
// the interval's ends across that polygon: the edges between them keep the root, those outside
// them are reached by turning at an interval end that is a corner (which becomes the root).
// f = g + the shortest way from the root through the interval to the goal.
#pragma once

#include <cstdint>
#include <vector>

#include "planner/mesh/convex_mesh.h"
#include "planner/mesh/interval_search.h"

namespace plantsim::planner {

class PolygonSearch {
 public:
  explicit PolygonSearch(const ConvexMesh& mesh);
  IntervalPath find(Vec2 start, Vec2 goal);

 private:
  struct Node {
    std::int32_t polygon;  ///< entered; -1: the goal itself; -2: a turn on the way (for the path only)
    std::int32_t entry;    ///< the edge entered by, in `polygon`: from its left end to its right end
    Vec2 left, right;      ///< the interval, as seen from the root
    Vec2 root;
    std::int32_t root_vertex;  ///< -1 for the start
    std::int32_t parent;
    double g;
  };
  struct Entry {
    double f, g;
    std::int32_t node;
    bool operator<(const Entry& o) const { return f != o.f ? f > o.f : g < o.g; }
  };
  void expand(std::int32_t node);
  /// The root lies on the polygon's boundary: all of the polygon is in view.
  void expand_in_view(std::int32_t parent, Vec2 root, std::int32_t root_vertex, double g, std::int32_t polygon,
                      std::int32_t except, bool from_start);
  /// A successor through edge k of `polygon`, the part of it from `right` to `left`.
  void push(std::int32_t parent, std::int32_t polygon, std::int32_t k, Vec2 right, Vec2 left, Vec2 root,
            std::int32_t root_vertex, double g);
  void push_goal(std::int32_t parent, Vec2 root, double g);
  bool corner_improves(std::int32_t vertex, double g);
  double heuristic(Vec2 left, Vec2 right, Vec2 root) const;
  void queue_fresh();
  std::int32_t run(std::int64_t& expanded);

  const ConvexMesh& mesh_;
  std::vector<std::int32_t> portals_of_;  // per polygon, its edges with a polygon beyond
  Vec2 goal_;
  std::vector<std::uint32_t> goal_stamp_;  // polygons holding the goal: == search_
  std::vector<Node> nodes_, fresh_;
  std::vector<Entry> open_;
  std::vector<double> best_;  // per vertex, the cheapest turn there this search
  std::vector<std::uint32_t> stamp_;
  std::uint32_t search_ = 0;
};

}  // namespace plantsim::planner
