// The open list's entry of the visibility graph's lazy A* searches (the planner's and the
// replanning overlay's): an edge pushed untested, its visibility tested when it is popped.
#pragma once

#include <cstdint>
#include <functional>
#include <queue>
#include <vector>

namespace plantsim::planner {

struct LazyEntry {
  /// candidate: the index among the parent's candidate edges, or kUntested for an edge the
  /// graph holds no verdict on (from the start, to the goal, to an added corner).
  static constexpr std::int32_t kUntested = -1;
  double f, g;
  std::int32_t node, parent, candidate;
  /// Lowest f first; on ties deeper first, then by node and parent, so that the order (and with
  /// it the path among equal ones) never depends on the heap's internals.
  bool operator>(const LazyEntry& o) const {
    if (f != o.f) return f > o.f;
    if (g != o.g) return g < o.g;
    if (node != o.node) return node > o.node;
    return parent > o.parent;
  }
};

using LazyOpenList =
    std::priority_queue<LazyEntry, std::vector<LazyEntry>, std::greater<LazyEntry>>;

}  // namespace plantsim::planner
