// Tarjan's bridge finding over the mesh's dual graph, with an explicit stack.
#include "planner/mesh/dead_ends.h"

#include <algorithm>

namespace plantsim::planner {

DeadEnds::DeadEnds(const std::vector<std::int32_t>& first,
                   const std::vector<std::int32_t>& neighbour) {
  const std::int32_t count = first.empty() ? 0 : static_cast<std::int32_t>(first.size()) - 1;
  place_.assign(count, Place{});
  std::vector<std::int32_t> parent(count, -1), low(count), next(count);
  std::vector<bool> parent_skipped(count, false);
  std::vector<std::int32_t> stack;
  std::int32_t clock = 0;
  for (std::int32_t root = 0; root < count; ++root) {
    if (place_[root].enter >= 0) continue;
    place_[root].enter = low[root] = clock++;
    place_[root].root = root;
    next[root] = first[root];
    stack.push_back(root);
    while (!stack.empty()) {
      const std::int32_t n = stack.back();
      if (next[n] < first[n + 1]) {
        const std::int32_t m = neighbour[next[n]++];
        if (m < 0) continue;
        // The edge back to the parent is the tree edge once; a second one is a parallel edge.
        if (m == parent[n] && !parent_skipped[n]) {
          parent_skipped[n] = true;
          continue;
        }
        if (place_[m].enter >= 0) {
          low[n] = std::min(low[n], place_[m].enter);
          continue;
        }
        parent[m] = n;
        place_[m].enter = low[m] = clock++;
        place_[m].root = root;
        next[m] = first[m];
        stack.push_back(m);
        continue;
      }
      stack.pop_back();
      place_[n].leave = clock;
      if (const std::int32_t p = parent[n]; p >= 0) {
        low[p] = std::min(low[p], low[n]);
        if (low[n] > place_[p].enter) place_[n].bridge_parent = p, ++bridges_;
      }
    }
  }
}

bool DeadEnds::bridge_path(std::int32_t from, std::int32_t to,
                           std::vector<std::int32_t>& path) const {
  path.clear();
  if (place_[from].root != place_[to].root) return false;
  // Up the forest from each end to where the two meet, every step a bridge.
  std::int32_t a = from;
  for (; !under(a, to); a = place_[a].bridge_parent) {
    if (place_[a].bridge_parent < 0) return false;
    path.push_back(a);
  }
  path.push_back(a);
  const std::size_t meet = path.size();
  for (std::int32_t b = to; b != a; b = place_[b].bridge_parent) {
    if (place_[b].bridge_parent < 0) return false;
    path.push_back(b);
  }
  std::reverse(path.begin() + static_cast<std::ptrdiff_t>(meet), path.end());
  return true;
}

void DeadEnds::set_goal(const std::int32_t* nodes, std::size_t count) {
  goal_.assign(nodes, nodes + count);
}

}  // namespace plantsim::planner
