// Dead ends of a mesh for a given goal: the parts of the free floor a shortest path to the
// goal never enters. An edge of the mesh's dual graph (cells joined where they share a portal)
// whose removal splits the graph, a bridge, is crossed at most once by a shortest path (crossing
// the same segment twice, the straight piece of it between the crossings is no longer), so the
// side of a bridge that holds no goal is never worth entering. Polyanya's authors prune single
// dead-end polygons (one way in); this prunes whole subtrees of polygons hanging off a bridge,
// which on maps whose mesh is nearly a tree (the any-angle benchmarks' StarCraft maps) is most
// of the map. Found once per mesh (Tarjan's bridges, iteratively: meshes have 10^5+ cells).
#pragma once

#include <cstdint>
#include <vector>

namespace plantsim::planner {

class DeadEnds {
 public:
  DeadEnds() = default;
  /// The dual graph: node n's neighbours are neighbour[first[n] .. first[n + 1]) (-1: none, a
  /// wall). Parallel edges between two nodes may appear (then neither is a bridge).
  DeadEnds(const std::vector<std::int32_t>& first, const std::vector<std::int32_t>& neighbour);
  /// The nodes holding the goal (one, or several when it is on their shared edge or vertex);
  /// none: no pruning (a search for every distance).
  void set_goal(const std::int32_t* nodes, std::size_t count);
  /// Crossing from node `from` into its neighbour `to` leads only away from every goal node.
  bool leads_nowhere(std::int32_t from, std::int32_t to) const {
    if (goal_.empty()) return false;
    if (place_[to].bridge_parent == from) return !any_goal_under(to);
    if (place_[from].bridge_parent == to) return !any_goal_above(from);
    return false;
  }
  /// The nodes from `from` to `to` (both included) when every edge between them is a bridge:
  /// then every way from one to the other crosses those edges, in that order. False (`path`
  /// then holds nothing of use) when they are apart or some step between them is no bridge.
  bool bridge_path(std::int32_t from, std::int32_t to, std::vector<std::int32_t>& path) const;
  /// Whether `node` lies on `to`'s side of the bridge from `from` to `to`.
  bool beyond(std::int32_t from, std::int32_t to, std::int32_t node) const {
    if (place_[to].bridge_parent == from) return under(to, node);
    return place_[node].root == place_[from].root && !under(from, node);
  }
  /// Bridges found (each counted once).
  std::int64_t bridge_count() const { return bridges_; }

 private:
  bool under(std::int32_t top, std::int32_t node) const {
    return place_[top].enter <= place_[node].enter && place_[node].enter < place_[top].leave;
  }
  bool any_goal_under(std::int32_t top) const {
    for (const std::int32_t g : goal_)
      if (under(top, g)) return true;
    return false;
  }
  // In the node's component (under its tree's root) but not under the node.
  bool any_goal_above(std::int32_t top) const {
    for (const std::int32_t g : goal_)
      if (under(place_[top].root, g) && !under(top, g)) return true;
    return false;
  }

  // Where a node is in a depth-first forest of the dual graph: its subtree is the nodes entered
  // in [enter, leave); the edge to its parent is a bridge when nothing in the subtree reaches
  // above it by another edge. One record per node: a search reads them together.
  struct Place {
    std::int32_t bridge_parent = -1;  ///< the parent, when the edge to it is a bridge; else -1
    std::int32_t root = -1;           ///< the root of its tree (its connected component)
    std::int32_t enter = -1, leave = 0;
  };
  std::vector<Place> place_;
  std::vector<std::int32_t> goal_;
  std::int64_t bridges_ = 0;
};

}  // namespace plantsim::planner
