// What an interval search answers (both meshes'), and how its path is read back from the
// search's nodes: each node keeps its root and its parent, so the path is the roots from the
// goal's node back to the start's, each turn once.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::planner {

struct IntervalPath {
  bool found = false;
  std::vector<geom::Vec2> path;  ///< start .. goal, the corners it turns at between
  std::int64_t expanded = 0;
  std::int64_t generated = 0;
  std::size_t over_budget_bytes = 0;  ///< not 0: the search stopped there, past its memory budget
  bool through_channel = false;  ///< answered by the funnel through a row of bridges, no search
};

/// What a search's nodes and queue hold, in bytes (their capacity: what was allocated).
template <typename Node, typename Entry>
std::size_t held_bytes(const std::vector<Node>& nodes, const std::vector<Entry>& open) {
  return nodes.capacity() * sizeof(Node) + open.capacity() * sizeof(Entry);
}

/// Fills `out` from the node `reached` (the goal's; -1: none was) back through its parents.
template <typename Node>
void read_back(const std::vector<Node>& nodes, std::int32_t reached, geom::Vec2 goal,
               IntervalPath& out) {
  if (reached >= 0) {
    out.found = true;
    out.path.push_back(goal);
    for (std::int32_t i = reached; i >= 0; i = nodes[i].parent)
      if (!(nodes[i].root == out.path.back())) out.path.push_back(nodes[i].root);
    std::reverse(out.path.begin(), out.path.end());
  }
  out.generated = static_cast<std::int64_t>(nodes.size());
}

}  // namespace plantsim::planner
