// Exact any-angle shortest paths by interval search over the free-space mesh: the method of
// Polyanya (Cui, Harabor and Grastien, IJCAI 2017) on plantsim's mesh of rectangles. A search
// node is an interval of a portal every point of which the node's root sees; expanding it
// projects the interval across the next cell (successors keep the root) and, where the
// interval ends at an obstacle corner, turns there (the corner becomes the root). f = g + the
// length of the shortest way from the root through the interval to the goal. A corner reached
// at a greater cost than before is not expanded again (root-level pruning). No graph is built:
// a query touches only the cells it sweeps.
#pragma once

#include <cstdint>
#include <vector>

#include "planner/mesh/dead_ends.h"
#include "planner/mesh/free_space_mesh.h"
#include "planner/mesh/interval_path.h"
#include "planner/mesh/mesh_search.h"
#include "planner/search_budget.h"

namespace plantsim::planner {

class IntervalSearch {
 public:
  explicit IntervalSearch(const FreeSpaceMesh& mesh);
  IntervalPath find(Vec2 start, Vec2 goal);
  /// Picks `count` landmarks (each the free corner farthest from those before) and stores the
  /// exact shortest distance from each to every cell corner. Queries then take as heuristic
  /// also the landmarks' lower bound |d(L, goal) - d(L, root)| (ALT, Goldberg and Harrelson
  /// 2005), which sees the detours the straight line does not; answers are unchanged.
  void add_landmarks(int count);
  /// Off: the search also enters the dead ends (DeadEnds), as a measure of what pruning them saves.
  void set_dead_end_pruning(bool on) { prune_dead_ends_ = on; }
  /// A query whose nodes and queue pass this many bytes stops, unanswered (over_budget_bytes).
  void set_memory_budget(std::size_t bytes) { budget_bytes_ = bytes; }
  int landmark_count() const { return landmarks_; }
  /// Exact shortest distance from `source` to every cell corner (4 per cell: x low y low, x high
  /// y low, x low y high, x high y high), infinity where unreachable: a search with no goal.
  std::vector<double> distances_to_corners(Vec2 source);

 private:
  struct Node {
    std::int32_t portal;  ///< -1: the goal itself; -2: a corner on the way (for the path only)
    std::int32_t cell;    ///< the cell the node opens into
    double ya, yb;        ///< the interval on the portal's line
    Vec2 root;
    std::int32_t root_vertex;  ///< the portal end it is (2 * portal + end), -1 for the start
    std::int32_t parent;
    double g;
  };
  /// Forgets the last search (its nodes, queue and the corners' best arrivals).
  void begin(Vec2 goal);
  /// The first root, with every portal of the cells holding it in view, queued.
  void queue_source(Vec2 source, const std::vector<std::int32_t>& cells);
  void expand(std::int32_t node);
  void queue_fresh();
  double priority(const Node& n) const;  // f - g: the heuristic, 0 while measuring distances
  /// The root lies in the closed cell: every portal of it is in view.
  void expand_in_view(std::int32_t parent, Vec2 root, std::int32_t root_vertex, double g,
                      std::int32_t cell, std::int32_t except);
  /// A successor into `cell` (not a dead end: callers look first).
  void push(std::int32_t parent, std::int32_t portal, std::int32_t cell, double ya, double yb,
            Vec2 root, std::int32_t root_vertex, double g);
  /// A turn at a portal's end, reached from `from`: kept unless that corner was reached more
  /// cheaply before, or as cheaply along the same line.
  bool corner_improves(std::int32_t vertex, double g, Vec2 from, Vec2 corner);
  void push_goal(std::int32_t parent, Vec2 root, double g);
  void push_along_line(std::int32_t parent, Vec2 from, double g, std::int32_t portal,
                       std::int32_t cell);
  double heuristic(double x, double ya, double yb, Vec2 root) const;
  double landmark_bound(std::int32_t root_vertex) const;
  void set_goal_bounds(std::int32_t goal_cell, Vec2 goal);
  void record_corners(std::int32_t cell, Vec2 r, double g, double x, double ya, double yb, bool low,
                      Vec2 a, double ga, bool high, Vec2 b, double gb);
  void record_corners_in_view(std::int32_t cell, Vec2 r, double g);
  void number_points();
  template <typename F>
  void for_each_point(std::int32_t cell, F&& f) const;
  /// The goal's node, or -1: none reached, or the search passed its memory budget (then
  /// `out.over_budget_bytes` says how far).
  std::int32_t run(IntervalPath& out);
  std::int32_t other_side(std::int32_t portal, std::int32_t cell) const;

  const FreeSpaceMesh& mesh_;
  DeadEnds dead_ends_;
  bool prune_dead_ends_ = true;
  Vec2 goal_;
  MeshSearchQueue<Node> q_;
  struct Arrival {
    double g = 0;
    Vec2 dir;  // unit direction it came in along
  };
  std::vector<Arrival> best_;         // per portal end (2 * portal + end)
  std::vector<std::uint32_t> stamp_;  // which search best_ holds
  std::uint32_t search_ = 0;
  std::size_t budget_bytes_ = kSearchMemoryBudgetBytes;
  // Landmarks: distances from each to every cell corner and portal end, landmark-minor.
  int landmarks_ = 0;
  bool use_landmarks_ = false;  // this query: landmarks, and the goal not at a pinch
  std::vector<double> corner_distance_, end_distance_;
  std::vector<double> goal_low_, goal_high_;  // bounds on each landmark's distance to the goal
  double start_bound_ = 0;                    // the landmarks' bound for nodes rooted at the start
  std::vector<double>* flood_ = nullptr;      // while measuring distances: by point number
  std::vector<std::int32_t> point_of_corner_,
      point_of_end_;  // cell corners and portal ends, numbered
  std::size_t points_ = 0;
};

}  // namespace plantsim::planner
