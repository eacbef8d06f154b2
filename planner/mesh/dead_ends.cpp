// Tarjan's bridge finding over the mesh's dual graph, with an explicit stack.
#include "planner/mesh/dead_ends.h"

#include <algorithm>

namespace plantsim::planner {

DeadEnds::DeadEnds(const std::vector<std::int32_t>& first, const std::vector<std::int32_t>& neighbour) {
  const std::int32_t count = first.empty() ? 0 : static_cast<std::int32_t>(first.size()) - 1;
  parent_.assign(count, -1);
  root_.assign(count, -1);
  enter_.assign(count, -1);
  leave_.assign(count, 0);
  bridge_to_parent_.assign(count, false);
  std::vector<std::int32_t> low(count), next(count);
  std::vector<bool> parent_skipped(count, false);
  std::vector<std::int32_t> stack;
  std::int32_t clock = 0;
  for (std::int32_t root = 0; root < count; ++root) {
    if (enter_[root] >= 0) continue;
    enter_[root] = low[root] = clock++;
    root_[root] = root;
    next[root] = first[root];
    stack.push_back(root);
    while (!stack.empty()) {
      const std::int32_t n = stack.back();
      if (next[n] < first[n + 1]) {
        const std::int32_t m = neighbour[next[n]++];
        if (m < 0) continue;
        // The edge back to the parent is the tree edge once; a second one is a parallel edge.
        if (m == parent_[n] && !parent_skipped[n]) {
          parent_skipped[n] = true;
          continue;
        }
        if (enter_[m] >= 0) {
          low[n] = std::min(low[n], enter_[m]);
          continue;
        }
        parent_[m] = n;
        root_[m] = root;
        enter_[m] = low[m] = clock++;
        next[m] = first[m];
        stack.push_back(m);
        continue;
      }
      stack.pop_back();
      leave_[n] = clock;
      if (const std::int32_t p = parent_[n]; p >= 0) {
        low[p] = std::min(low[p], low[n]);
        if (low[n] > enter_[p]) bridge_to_parent_[n] = true, ++bridges_;
      }
    }
  }
}

void DeadEnds::set_goal(const std::int32_t* nodes, std::size_t count) { goal_.assign(nodes, nodes + count); }

}  // namespace plantsim::planner
