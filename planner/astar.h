// Best-first search over an implicit graph of dense integer node ids: A* with an admissible
// heuristic, Dijkstra when the heuristic is zero. Neighbours are generated on demand by the
// caller, so graphs whose edges are expensive to find are only explored where the search goes.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

namespace plantsim::planner {

struct SearchStats {
  std::int64_t expanded = 0;  ///< nodes taken off the open list for the first time
  std::int64_t pushed = 0;    ///< open-list insertions
};

struct SearchResult {
  bool found = false;
  double cost = std::numeric_limits<double>::infinity();
  std::vector<std::int32_t> nodes;    ///< start .. goal
  std::size_t over_budget_bytes = 0;  ///< not 0: the search stopped there, past its memory budget
  SearchStats stats;
};

/// `neighbours(u, emit)` must call emit(v, edge_cost) for each successor of u.
template <typename Heuristic, typename Neighbours>
SearchResult best_first_search(std::int32_t node_count, std::int32_t start, std::int32_t goal,
                               Heuristic&& h, Neighbours&& neighbours) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> g(node_count, kInf);
  std::vector<std::int32_t> parent(node_count, -1);
  std::vector<char> closed(node_count, 0);
  struct Entry {
    double f;
    double g;
    std::int32_t node;
    // Ties on f broken towards larger g (deeper), then lower id, for deterministic order.
    bool operator>(const Entry& o) const {
      if (f != o.f) return f > o.f;
      if (g != o.g) return g < o.g;
      return node > o.node;
    }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  SearchResult result;
  g[start] = 0.0;
  open.push({h(start), 0.0, start});
  ++result.stats.pushed;
  while (!open.empty()) {
    const Entry e = open.top();
    open.pop();
    if (closed[e.node] || e.g > g[e.node]) continue;
    closed[e.node] = 1;
    ++result.stats.expanded;
    if (e.node == goal) break;
    neighbours(e.node, [&](std::int32_t v, double cost) {
      if (closed[v]) return;
      const double ng = e.g + cost;
      if (ng < g[v]) {
        g[v] = ng;
        parent[v] = e.node;
        open.push({ng + h(v), ng, v});
        ++result.stats.pushed;
      }
    });
  }
  if (g[goal] < kInf) {
    result.found = true;
    result.cost = g[goal];
    for (std::int32_t v = goal; v != -1; v = parent[v]) result.nodes.push_back(v);
    std::reverse(result.nodes.begin(), result.nodes.end());
  }
  return result;
}

}  // namespace plantsim::planner
