// The reduced visibility graph of an ObstacleMap: vertices are the convex corners of the
// obstacle union (a corner is kept only when the three quadrants around it other than its
// own rectangle's are free), edges join mutually visible vertices whose segment is tangent to
// the obstacle at both ends (bitangent), the only edges a shortest path can use. Edges are
// found lazily, per vertex, the first time a search expands it, and kept for later queries.
// Not safe for concurrent queries: give each thread its own graph.
#pragma once

#include <cstdint>
#include <vector>

#include "planner/obstacle_map.h"

namespace plantsim::planner {

struct GraphVertex {
  Vec2 p;
  std::int8_t turn_sign;  ///< sx*sy of the free diagonal at this corner (+1 or -1)
};

struct GraphEdge {
  std::int32_t to;
  double length;
};

class VisibilityGraph {
 public:
  explicit VisibilityGraph(const ObstacleMap& map);

  const ObstacleMap& map() const { return map_; }
  const std::vector<GraphVertex>& vertices() const { return vertices_; }

  /// True when a path through vertex v may leave along direction d (v's obstacle stays on
  /// one side of the line). Both d and -d give the same answer.
  static bool tangent(const GraphVertex& v, Vec2 d);

  /// Bitangent visible neighbours of vertex v, computed on first use.
  const std::vector<GraphEdge>& neighbours(std::int32_t v) const;

  std::int64_t edges_found() const { return edges_found_; }
  std::int64_t segment_tests() const { return segment_tests_; }
  void count_segment_test() const { ++segment_tests_; }

 private:
  const ObstacleMap& map_;
  std::vector<GraphVertex> vertices_;
  mutable std::vector<std::vector<GraphEdge>> adjacency_;
  mutable std::vector<char> adjacency_ready_;
  mutable std::int64_t edges_found_ = 0;
  mutable std::int64_t segment_tests_ = 0;
};

}  // namespace plantsim::planner
