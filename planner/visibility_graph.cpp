// Convex-corner extraction and lazy bitangent edge discovery.
#include "planner/visibility_graph.h"

#include <algorithm>
#include <tuple>

#include "geometry/predicates.h"

namespace plantsim::planner {
namespace {

int sign(double v) { return (v > 0) - (v < 0); }

}  // namespace

VisibilityGraph::VisibilityGraph(const ObstacleMap& map) : map_(map) {
  const auto& rects = map.rects();
  for (std::size_t i = 0; i < map.obstacle_count(); ++i) {
    const Rect& r = rects[i];
    // Each corner with the diagonal pointing away from its rectangle.
    const struct { Vec2 c; int sx, sy; } corners[4] = {{{r.xmin, r.ymin}, -1, -1},
                                                       {{r.xmax, r.ymin}, 1, -1},
                                                       {{r.xmax, r.ymax}, 1, 1},
                                                       {{r.xmin, r.ymax}, -1, 1}};
    for (const auto& k : corners) {
      if (!geom::in_closed_rect(map.free_floor(), k.c)) continue;
      const auto self = static_cast<std::int32_t>(i);
      if (map.quadrant_occupied(k.c, k.sx, k.sy, self) ||
          map.quadrant_occupied(k.c, -k.sx, k.sy, self) ||
          map.quadrant_occupied(k.c, k.sx, -k.sy, self))
        continue;
      vertices_.push_back({k.c, static_cast<std::int8_t>(k.sx * k.sy)});
    }
  }
  // Nested rectangles sharing a corner give the same vertex twice.
  std::sort(vertices_.begin(), vertices_.end(), [](const GraphVertex& a, const GraphVertex& b) {
    return std::tie(a.p.x, a.p.y, a.turn_sign) < std::tie(b.p.x, b.p.y, b.turn_sign);
  });
  vertices_.erase(std::unique(vertices_.begin(), vertices_.end(),
                              [](const GraphVertex& a, const GraphVertex& b) {
                                return a.p == b.p && a.turn_sign == b.turn_sign;
                              }),
                  vertices_.end());
  adjacency_.resize(vertices_.size());
  adjacency_ready_.assign(vertices_.size(), 0);
}

bool VisibilityGraph::tangent(const GraphVertex& v, Vec2 d) {
  return sign(d.x) * sign(d.y) != v.turn_sign;
}

const std::vector<GraphEdge>& VisibilityGraph::neighbours(std::int32_t v) const {
  if (adjacency_ready_[v]) return adjacency_[v];
  const GraphVertex& a = vertices_[v];
  auto& out = adjacency_[v];
  for (std::size_t w = 0; w < vertices_.size(); ++w) {
    if (static_cast<std::int32_t>(w) == v) continue;
    const GraphVertex& b = vertices_[w];
    const Vec2 d = b.p - a.p;
    if (!tangent(a, d) || !tangent(b, d)) continue;
    ++segment_tests_;
    if (map_.segment_free(a.p, b.p))
      out.push_back({static_cast<std::int32_t>(w), geom::distance(a.p, b.p)});
  }
  edges_found_ += static_cast<std::int64_t>(out.size());
  adjacency_ready_[v] = 1;
  return out;
}

}  // namespace plantsim::planner
