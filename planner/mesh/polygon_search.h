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

#include "planner/mesh/channel_funnel.h"
#include "planner/mesh/convex_mesh.h"
#include "planner/mesh/dead_ends.h"
#include "planner/mesh/interval_path.h"
#include "planner/mesh/mesh_search.h"
#include "planner/search_budget.h"

namespace plantsim::planner {

class PolygonSearch {
 public:
  explicit PolygonSearch(const ConvexMesh& mesh);
  IntervalPath find(Vec2 start, Vec2 goal);
  /// As IntervalSearch::add_landmarks: `count` landmarks (each the corner farthest from those
  /// before), the exact distance from each to every mesh vertex stored, and their (ALT) lower
  /// bound taken in the heuristic as well. Answers are unchanged.
  void add_landmarks(int count);
  /// Off: the search also enters the dead ends (DeadEnds), and a query whose ends are joined by
  /// bridges only is searched too, not pulled taut through its channel: a measure of what the
  /// dead ends save.
  void set_dead_end_pruning(bool on) { prune_dead_ends_ = on; }
  /// A query whose nodes and queue pass this many bytes stops, unanswered (over_budget_bytes).
  void set_memory_budget(std::size_t bytes) { budget_bytes_ = bytes; }
  int landmark_count() const { return landmarks_; }
  /// Exact shortest distance from `source` to every mesh vertex, infinity where unreachable: a
  /// search with no goal.
  std::vector<double> distances_to_vertices(Vec2 source);

 private:
  struct Node {
    std::int32_t
        polygon;  ///< entered; -1: the goal itself; -2: a turn on the way (for the path only)
    std::int32_t entry;  ///< the edge entered by, in `polygon`: from its left end to its right end
    Vec2 left, right;    ///< the interval, as seen from the root
    Vec2 root;
    std::int32_t root_vertex;  ///< -1 for the start
    std::int32_t parent;
    double g;
  };
  void expand(std::int32_t node);
  /// The root lies on the polygon's boundary: all of the polygon is in view.
  void expand_in_view(std::int32_t parent, Vec2 root, std::int32_t root_vertex, double g,
                      std::int32_t polygon, std::int32_t except, bool from_start);
  /// A successor through edge k of `polygon`, the part of it from `right` to `left` (the
  /// polygon beyond is not a dead end: callers look first).
  void push(std::int32_t parent, std::int32_t polygon, std::int32_t k, Vec2 right, Vec2 left,
            Vec2 root, std::int32_t root_vertex, double g);
  void push_goal(std::int32_t parent, Vec2 root, double g);
  bool corner_improves(std::int32_t vertex, double g);
  double heuristic(Vec2 left, Vec2 right, Vec2 root) const;
  double landmark_bound(std::int32_t root_vertex);
  bool at_pinch(const std::vector<std::int32_t>& polygons, Vec2 p) const;
  /// Bounds on each landmark's distance to p, from the vertices of the polygons holding it.
  void bound_landmark_distances(const std::vector<std::int32_t>& polygons, Vec2 p,
                                std::vector<double>& low, std::vector<double>& high) const;
  /// While measuring distances: what the node's view of its polygon tells of its vertices.
  void record_view(std::int32_t polygon, Vec2 r, double g, Vec2 uR, Vec2 uL, bool right, Vec2 B,
                   double gR, bool left, Vec2 A, double gL);
  void record_in_view(std::int32_t polygon, Vec2 r, double g);
  /// When every way from the start to the goal crosses the same row of polygons (each step a
  /// bridge), the path pulled taut through it (funnel_path) into `out`; else false.
  bool through_channel(const std::vector<std::int32_t>& first,
                       const std::vector<std::int32_t>& last, Vec2 start, Vec2 goal,
                       IntervalPath& out);
  void begin(Vec2 goal);
  void queue_fresh();
  double priority(const Node& n);  // f - g: the heuristic, 0 while measuring distances
  /// The goal's node, or -1: none reached, or the search passed its memory budget (then
  /// `out.over_budget_bytes` says how far).
  std::int32_t run(IntervalPath& out);

  const ConvexMesh& mesh_;
  DeadEnds dead_ends_;
  bool prune_dead_ends_ = true;
  std::vector<std::int32_t> channel_;  // the bridge path of a query, reused
  std::vector<Portal> portals_;
  Vec2 goal_;
  std::vector<std::uint32_t> goal_stamp_;  // polygons holding the goal: == search_
  MeshSearchQueue<Node> q_;
  std::vector<double> best_;  // per vertex, the cheapest turn there this search
  // Landmarks: distances from each to every vertex, landmark-minor (NaN: unreachable).
  int landmarks_ = 0;
  bool use_landmarks_ = false;  // this query: landmarks, and neither end at a pinch
  std::vector<double> vertex_distance_;
  std::vector<double> goal_low_, goal_high_, start_low_, start_high_;
  double start_bound_ = 0;                // the landmarks' bound for nodes rooted at the start
  std::vector<double>* flood_ = nullptr;  // while measuring distances: per vertex
  std::vector<std::uint32_t> stamp_;
  // Per vertex, its landmark bound this search (many nodes share a root): valid where
  // bound_stamp_ == search_.
  std::vector<double> bound_;
  std::vector<std::uint32_t> bound_stamp_;
  std::uint32_t search_ = 0;
  std::size_t budget_bytes_ = kSearchMemoryBudgetBytes;
};

}  // namespace plantsim::planner
