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

#include "planner/mesh/free_space_mesh.h"

namespace plantsim::planner {

struct IntervalPath {
  bool found = false;
  std::vector<Vec2> path;  ///< start .. goal, the corners it turns at between
  std::int64_t expanded = 0;
  std::int64_t generated = 0;
};

class IntervalSearch {
 public:
  explicit IntervalSearch(const FreeSpaceMesh& mesh);
  IntervalPath find(Vec2 start, Vec2 goal);

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
  struct Entry {
    double f, g;
    std::int32_t node;
    bool operator<(const Entry& o) const { return f != o.f ? f > o.f : g < o.g; }
  };
  void expand(std::int32_t node);
  void expand_and_queue(std::int32_t node, std::int64_t& expanded);
  void queue_fresh();
  void push_open(Entry e);
  /// The root lies in the closed cell: every portal of it is in view.
  void expand_in_view(std::int32_t parent, Vec2 root, std::int32_t root_vertex, double g, std::int32_t cell,
                      std::int32_t except);
  void push(std::int32_t parent, std::int32_t portal, std::int32_t cell, double ya, double yb, Vec2 root,
            std::int32_t root_vertex, double g);
  /// A turn at a portal's end, reached from `from`: kept unless that corner was reached more
  /// cheaply before, or as cheaply along the same line.
  bool corner_improves(std::int32_t vertex, double g, Vec2 from, Vec2 corner);
  void push_goal(std::int32_t parent, Vec2 root, double g);
  void push_along_line(std::int32_t parent, Vec2 from, double g, std::int32_t portal, std::int32_t cell);
  double heuristic(double x, double ya, double yb, Vec2 root) const;
  std::int32_t other_side(std::int32_t portal, std::int32_t cell) const;

  const FreeSpaceMesh& mesh_;
  Vec2 goal_;
  std::vector<Node> nodes_;
  std::vector<Node> fresh_;  // the successors of the node being expanded
  std::vector<Entry> open_;  // a binary heap (std::push_heap), its storage kept across queries
  struct Arrival {
    double g = 0;
    Vec2 dir;  // unit direction it came in along
  };
  std::vector<Arrival> best_;          // per portal end (2 * portal + end)
  std::vector<std::uint32_t> stamp_;   // which search best_ holds
  std::uint32_t search_ = 0;
};

}  // namespace plantsim::planner
