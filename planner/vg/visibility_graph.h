// The reduced visibility graph of an ObstacleMap: vertices are the convex corners of the
// obstacle union (a corner is kept only when the three quadrants around it other than its
// own rectangle's are free), edges join mutually visible vertices whose segment is tangent to
// the obstacle at both ends (bitangent), the only edges a shortest path can use.
// Work is done lazily and kept for later queries: a vertex's candidate edges (tangent at both
// ends, not yet known to be visible) are gathered the first time a search expands it, and an
// edge's visibility is tested only when a search pops it. Candidates are gathered outward
// ring by ring over the obstacle grid, stopping once every direction is known to be blocked
// nearer than the ring reached, so the cost follows local clutter, not the world's size; a
// candidate that lies beyond one of the rectangles met, in a direction strictly inside that
// rectangle's view, is dropped there (most hidden pairs: 99 % of ArcticStation's candidates
// were hidden before this), so segment tests are left for the pairs a union of rectangles hides.
// Not safe for concurrent queries: give each thread its own graph.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "planner/obstacle_map.h"
#include "planner/vg/angle_coverage.h"

namespace plantsim::planner {

struct GraphVertex {
  Vec2 p;
  Vec2 inside;         ///< a point inside this corner's rectangle (the side a path bends around)
  std::int8_t sx, sy;  ///< the free diagonal at this corner; its rectangle lies towards (-sx, -sy)
  int turn_sign() const { return sx * sy; }
};

struct GraphEdge {
  std::int32_t to;
  double length;
};

class VisibilityGraph {
 public:
  explicit VisibilityGraph(const ObstacleMap& map);
  /// The graph of `map`, a copy of `base`'s map with the (inflated) rectangles `changed` added
  /// or removed: what `base` found for a vertex whose scan no changed rectangle reaches is
  /// taken over as it is; the rest is found anew, lazily.
  VisibilityGraph(const ObstacleMap& map, const VisibilityGraph& base,
                  const std::vector<Rect>& changed);
  /// Vertices whose candidates were taken over from a base graph.
  std::int64_t reused() const { return reused_; }

  const ObstacleMap& map() const { return map_; }
  const std::vector<GraphVertex>& vertices() const { return vertices_; }

  /// True when a path through vertex v may leave along direction d (v's obstacle stays on
  /// one side of the line). Both d and -d give the same answer.
  static bool tangent(const GraphVertex& v, Vec2 d);

  /// Candidate edges of vertex v: tangent at both ends and not ruled out by the ring
  /// search; visibility is not yet tested. Gathered on first use.
  const std::vector<GraphEdge>& candidates(std::int32_t v) const;

  /// Whether candidate edge i of vertex v is visible, tested once and remembered.
  bool candidate_visible(std::int32_t v, std::size_t i) const;

  /// Tests every remaining candidate of v and keeps only the visible ones, so that later
  /// searches through v push exact edges only. Candidate indices change: call between searches
  /// or right after candidates(v), before pushing.
  void resolve(std::int32_t v) const;
  bool resolved(std::int32_t v) const { return candidates_ready_[v] == 2; }

  /// True when a shortest path may go prev -> v -> next: it bends around v's own rectangle,
  /// or goes straight on. Exact.
  bool taut(Vec2 prev, std::int32_t v, Vec2 next) const;

  /// Candidate edges from an arbitrary point p (tangent at the vertex end only).
  void candidates_from_point(Vec2 p, std::vector<GraphEdge>& out) const;

  /// Exact visibility test, counted in the statistics.
  bool visible(Vec2 a, Vec2 b) const {
    ++segment_tests_;
    return map_.segment_free(a, b);
  }

  /// Edges tested and found visible so far (each once).
  std::vector<std::pair<std::int32_t, std::int32_t>> visible_edges() const;

  std::int64_t edges_found() const { return edges_found_; }
  std::int64_t candidates_gathered() const { return candidates_gathered_; }
  /// What the candidates kept so far take (each edge and its verdict, as allocated), in bytes.
  std::size_t candidate_bytes() const { return candidate_bytes_; }
  std::int64_t segment_tests() const { return segment_tests_; }

 private:
  void scan(Vec2 u, const GraphVertex* self, std::int32_t self_index,
            std::vector<GraphEdge>& out) const;
  void add_span(AngleCoverage& coverage, Vec2 u, const Rect& r) const;
  void add_big_rect_spans(AngleCoverage& coverage, Vec2 u, const Rect& square) const;
  void drop_hidden(Vec2 u, std::vector<GraphEdge>& out, std::size_t first) const;
  std::size_t bytes_of(std::size_t v) const {
    return candidates_[v].capacity() * sizeof(GraphEdge) +
           verdict_[v].capacity() * sizeof(std::int8_t);
  }

  struct Span {  // directions (lo, hi) a rectangle hides beyond `depth`, its farthest corner
    double depth, lo, hi;
  };

  const ObstacleMap& map_;
  std::vector<GraphVertex> vertices_;
  std::vector<std::vector<std::int32_t>> vertices_in_cell_;
  mutable std::vector<std::vector<GraphEdge>> candidates_;
  mutable std::vector<std::vector<std::int8_t>> verdict_;  // per candidate: -1 unknown, 0, 1
  mutable std::vector<char> candidates_ready_;
  mutable std::vector<Rect> scan_box_;  // per vertex, the square its scan covered
  std::int64_t reused_ = 0;
  mutable std::int64_t candidates_gathered_ = 0;
  mutable std::size_t candidate_bytes_ = 0;
  mutable std::vector<std::uint32_t> rect_seen_;  // stamp per rectangle, for one scan
  mutable std::uint32_t scan_stamp_ = 0;
  mutable std::vector<std::int32_t> big_rects_;  // scratch: rectangles reaching past a ring
  mutable std::vector<Span> spans_;              // scratch: every rectangle's span in one scan
  mutable std::vector<Span> by_shell_;           // scratch: spans_ bucketed by depth
  mutable std::vector<std::size_t> nearer_than_, cand_at_,
      fill_at_;                                   // scratch: the bucket sorts' counts
  mutable std::vector<GraphEdge> cand_by_shell_;  // scratch: candidates bucketed
  mutable std::int64_t edges_found_ = 0;
  mutable std::int64_t segment_tests_ = 0;
};

}  // namespace plantsim::planner
