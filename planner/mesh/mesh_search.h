// The A* skeleton both mesh searches share (interval_search over rectangles, polygon_search over
// convex polygons, after Polyanya): every node is kept for the path's read-back, the open list is
// a binary heap of (f, g, node), a node whose root was reached more cheaply since it was queued is
// dropped, a node's successors are gathered in `fresh`, and a lone successor (a corridor) is
// expanded at once: its f is no smaller than its parent's, so A* would take it next anyway, and
// the queue is spared (Polyanya's intermediate pruning). Each search supplies what a node is, how
// it expands, and its heuristic.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "planner/mesh/interval_path.h"

namespace plantsim::planner {

/// An open-list entry: the least f on top, ties to the larger g (deeper).
struct MeshOpenEntry {
  double f, g;
  std::int32_t node;
  bool operator<(const MeshOpenEntry& o) const { return f != o.f ? f > o.f : g < o.g; }
};

template <typename Node>
struct MeshSearchQueue {
  std::vector<Node> nodes;
  std::vector<Node> fresh;          ///< the successors of the node being expanded
  std::vector<MeshOpenEntry> open;  ///< a binary heap, its storage kept across queries

  void clear() {
    nodes.clear();
    open.clear();
  }
  void push(MeshOpenEntry e) {
    open.push_back(e);
    std::push_heap(open.begin(), open.end());
  }
  /// A node that is already the goal's (f = g), queued.
  void push_goal(const Node& n, double g) {
    nodes.push_back(n);
    push({g, g, static_cast<std::int32_t>(nodes.size() - 1)});
  }
  /// The gathered successors kept and queued, each with f = g + h(node).
  template <typename Heuristic>
  void queue_fresh(Heuristic&& h) {
    for (const Node& n : fresh) {
      nodes.push_back(n);
      push({n.g + h(n), n.g, static_cast<std::int32_t>(nodes.size() - 1)});
    }
  }
  /// Expands node `index` into `fresh` (expand(i) fills it), following lone successors at once,
  /// then queues what it found.
  template <typename Expand, typename Heuristic>
  void expand_and_queue(std::int32_t index, std::int64_t& expanded, Expand&& expand,
                        Heuristic&& h) {
    fresh.clear();
    expand(index);
    ++expanded;
    while (fresh.size() == 1) {
      nodes.push_back(fresh.front());
      fresh.clear();
      expand(static_cast<std::int32_t>(nodes.size() - 1));
      ++expanded;
    }
    queue_fresh(h);
  }
  /// The goal's node (is_goal), or -1: none reached, or the nodes and queue passed
  /// `budget_bytes` (then `out.over_budget_bytes` says how far). `stale(node)`: reached more
  /// cheaply since it was queued.
  template <typename IsGoal, typename IsStale, typename Expand, typename Heuristic>
  std::int32_t run(std::size_t budget_bytes, IntervalPath& out, IsGoal&& is_goal, IsStale&& stale,
                   Expand&& expand, Heuristic&& h) {
    while (!open.empty()) {
      if (const std::size_t bytes = held_bytes(nodes, open); bytes > budget_bytes) {
        out.over_budget_bytes = bytes;
        return -1;
      }
      std::pop_heap(open.begin(), open.end());
      const MeshOpenEntry e = open.back();
      open.pop_back();
      const Node& n = nodes[e.node];
      if (is_goal(n)) return e.node;
      if (stale(n)) continue;
      expand_and_queue(e.node, out.expanded, expand, h);
    }
    return -1;
  }
};

}  // namespace plantsim::planner
