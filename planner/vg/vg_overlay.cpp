// A* over the map's visibility graph plus the added rectangles' corners.
#include "planner/vg/vg_overlay.h"

#include <chrono>
#include <limits>
#include <queue>

#include "geometry/polyline.h"
#include "geometry/predicates.h"
#include "planner/search_budget.h"
#include "util/stopwatch.h"

namespace plantsim::planner {
namespace {

bool inside_any(const std::vector<Rect>& rects, Vec2 p) {
  for (const Rect& r : rects)
    if (geom::in_open_rect(r, p)) return true;
  return false;
}

// The nearest point outside every added rectangle that the map leaves free: on the boundary of
// the rectangles that contain p (their sides and corners), or none.
std::optional<Vec2> out_of_added(const ObstacleMap& map, const std::vector<Rect>& added, Vec2 p) {
  std::optional<Vec2> best;
  double best_d = std::numeric_limits<double>::infinity();
  std::vector<Vec2> tries;
  for (const Rect& r : added) {
    if (!geom::in_open_rect(r, p)) continue;
    tries.insert(tries.end(), {{r.xmin, p.y},
                               {r.xmax, p.y},
                               {p.x, r.ymin},
                               {p.x, r.ymax},
                               {r.xmin, r.ymin},
                               {r.xmax, r.ymin},
                               {r.xmax, r.ymax},
                               {r.xmin, r.ymax}});
  }
  // Exits of one rectangle may lie inside another: try every exit, and the exits' exits.
  for (std::size_t k = 0; k < tries.size() && k < 256; ++k) {
    const Vec2 q = tries[k];
    if (!inside_any(added, q)) {
      if (map.point_free(q) && geom::distance(p, q) < best_d)
        best_d = geom::distance(p, q), best = q;
      continue;
    }
    for (const Rect& r : added)
      if (geom::in_open_rect(r, q))
        tries.insert(tries.end(), {{r.xmin, q.y}, {r.xmax, q.y}, {q.x, r.ymin}, {q.x, r.ymax}});
  }
  return best;
}

}  // namespace

PlanResult plan_with_added(const VisibilityGraphPlanner& base, const std::vector<Rect>& added,
                           Vec2 start, Vec2 goal, OverlayStats* stats) {
  const auto t0 = std::chrono::steady_clock::now();
  const VisibilityGraph& graph = base.graph();
  const ObstacleMap& map = base.map();
  PlanResult out;
  OverlayStats local;
  OverlayStats& st = stats ? *stats : local;
  if (!map.point_free(start)) {
    out.status = PlanStatus::kStartBlocked;
    return out;
  }
  if (!map.point_free(goal) || inside_any(added, goal)) {
    out.status = PlanStatus::kGoalBlocked;
    return out;
  }
  if (inside_any(added, start)) {
    const auto moved = out_of_added(map, added, start);
    if (!moved) {
      out.status = PlanStatus::kStartBlocked;
      return out;
    }
    start = *moved;
    out.start_snapped = true;
  }
  // The added rectangles' corners that lie in free space.
  std::vector<Vec2> corners;
  for (const Rect& r : added)
    for (Vec2 c :
         {Vec2{r.xmin, r.ymin}, Vec2{r.xmax, r.ymin}, Vec2{r.xmax, r.ymax}, Vec2{r.xmin, r.ymax}})
      if (map.point_free(c) && !inside_any(added, c)) corners.push_back(c);

  const auto& vertices = graph.vertices();
  const auto n = static_cast<std::int32_t>(vertices.size());
  const auto m = static_cast<std::int32_t>(corners.size());
  const std::int32_t s = n + m, g = n + m + 1;
  auto point = [&](std::int32_t v) {
    return v < n ? vertices[v].p : v < s ? corners[v - n] : v == s ? start : goal;
  };
  auto clear_of_added = [&](Vec2 a, Vec2 b) {
    for (const Rect& r : added) {
      ++st.added_tests;
      if (geom::segment_enters_open_rect(a, b, r)) return false;
    }
    return true;
  };
  constexpr std::int32_t kUntested = -1;
  struct Entry {
    double f, g;
    std::int32_t node, parent, candidate;
    bool operator>(const Entry& o) const {
      if (f != o.f) return f > o.f;
      if (g != o.g) return g < o.g;
      if (node != o.node) return node > o.node;
      return parent > o.parent;
    }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  std::vector<char> closed(static_cast<std::size_t>(n + m + 2), 0);
  std::vector<std::int32_t> parent(static_cast<std::size_t>(n + m + 2), -1);
  auto push = [&](std::int32_t v, std::int32_t from, std::int32_t candidate, double gv) {
    if (!closed[v]) open.push({gv + geom::distance(point(v), goal), gv, v, from, candidate});
  };
  open.push({geom::distance(start, goal), 0.0, s, -1, kUntested});
  std::vector<GraphEdge> from_point;
  std::int64_t expanded = 0;
  std::size_t over_budget_bytes = 0;
  while (!open.empty()) {
    if (const std::size_t bytes = graph.candidate_bytes() + open.size() * sizeof(Entry);
        bytes > base.input().search_budget_bytes) {
      over_budget_bytes = bytes;
      break;
    }
    const Entry e = open.top();
    open.pop();
    if (closed[e.node]) continue;
    if (e.parent >= 0) {
      // The map's verdict (cached in its graph), then the added rectangles.
      const Vec2 a = point(e.parent), b = point(e.node);
      const bool on_map =
          e.candidate == kUntested
              ? graph.visible(a, b)
              : graph.candidate_visible(e.parent, static_cast<std::size_t>(e.candidate));
      if (!on_map || !clear_of_added(a, b)) continue;
    }
    closed[e.node] = 1;
    parent[e.node] = e.parent;
    ++expanded;
    if (e.node == g) break;
    const Vec2 u = point(e.node);
    if (e.node < n) {
      // A map vertex: its candidate edges, the added corners and the goal, where a shortest
      // path may bend around its own rectangle.
      const Vec2 prev = point(e.parent);
      const auto& cands = graph.candidates(e.node);
      st.base_candidates += static_cast<std::int64_t>(cands.size());
      for (std::size_t i = 0; i < cands.size(); ++i) {
        const std::int32_t to = cands[i].to;
        if (closed[to] || inside_any(added, vertices[to].p) ||
            !graph.taut(prev, e.node, vertices[to].p))
          continue;
        push(to, e.node, static_cast<std::int32_t>(i), e.g + cands[i].length);
      }
      for (std::int32_t k = 0; k < m; ++k)
        if (VisibilityGraph::tangent(vertices[e.node], corners[k] - u) &&
            graph.taut(prev, e.node, corners[k]))
          push(n + k, e.node, kUntested, e.g + geom::distance(u, corners[k]));
      if (VisibilityGraph::tangent(vertices[e.node], goal - u) && graph.taut(prev, e.node, goal))
        push(g, e.node, kUntested, e.g + geom::distance(u, goal));
      continue;
    }
    // The start or an added corner: the map's vertices by the tangent ring scan, every other
    // added corner, and the goal.
    from_point.clear();
    graph.candidates_from_point(u, from_point);
    for (const GraphEdge& c : from_point)
      if (!inside_any(added, vertices[c.to].p)) push(c.to, e.node, kUntested, e.g + c.length);
    for (std::int32_t k = 0; k < m; ++k)
      if (n + k != e.node) push(n + k, e.node, kUntested, e.g + geom::distance(u, corners[k]));
    push(g, e.node, kUntested, e.g + geom::distance(u, goal));
  }
  out.stats.expanded = expanded;
  out.stats.vertices = n + m;
  if (over_budget_bytes > 0) {
    out.status = PlanStatus::kSearchLimit;
    out.note = search_limit_note("vg (replanning round sensed obstacles)",
                                 base.input().search_budget_bytes, over_budget_bytes,
                                 "candidate edges and the queue");
  } else if (!closed[g]) {
    out.status = PlanStatus::kNoPath;
  } else {
    out.status = PlanStatus::kOk;
    std::vector<Vec2> reversed;
    for (std::int32_t v = g; v != -1; v = parent[v]) reversed.push_back(point(v));
    for (auto it = reversed.rbegin(); it != reversed.rend(); ++it)
      if (out.path.empty() || !(out.path.back() == *it)) out.path.push_back(*it);
    out.length = geom::polyline_length(out.path);
  }
  out.stats.query_ms = util::ms_since(t0);
  return out;
}

}  // namespace plantsim::planner
