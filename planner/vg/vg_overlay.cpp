// A* over the map's visibility graph plus the added rectangles' corners.
#include "planner/vg/vg_overlay.h"

#include <chrono>
#include <limits>
#include <optional>
#include <queue>
#include <utility>

#include "geometry/polyline.h"
#include "geometry/predicates.h"
#include "planner/search_budget.h"
#include "planner/vg/lazy_entry.h"
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

namespace {

// The added rectangles' corners that lie in free space.
std::vector<Vec2> free_corners(const ObstacleMap& map, const std::vector<Rect>& added) {
  std::vector<Vec2> corners;
  for (const Rect& r : added)
    for (Vec2 c :
         {Vec2{r.xmin, r.ymin}, Vec2{r.xmax, r.ymin}, Vec2{r.xmax, r.ymax}, Vec2{r.xmin, r.ymax}})
      if (map.point_free(c) && !inside_any(added, c)) corners.push_back(c);
  return corners;
}

// One query's A* over the map's vertices (0 .. n - 1), the added corners (n .. n + m - 1), the
// start (n + m) and the goal (n + m + 1).
class OverlaySearch {
 public:
  OverlaySearch(const VisibilityGraph& graph, const std::vector<Rect>& added,
                std::vector<Vec2> corners, Vec2 start, Vec2 goal, OverlayStats& stats)
      : graph_(graph),
        vertices_(graph.vertices()),
        added_(added),
        corners_(std::move(corners)),
        start_(start),
        goal_(goal),
        n_(static_cast<std::int32_t>(vertices_.size())),
        m_(static_cast<std::int32_t>(corners_.size())),
        s_(n_ + m_),
        g_(n_ + m_ + 1),
        closed_(static_cast<std::size_t>(n_ + m_ + 2), 0),
        parent_(static_cast<std::size_t>(n_ + m_ + 2), -1),
        stats_(stats) {
    open_.push({geom::distance(start, goal), 0.0, s_, -1, kUntested});
  }

  // Runs to the goal or until the search holds more than the budget; the bytes it held then.
  std::size_t run(std::size_t budget_bytes) {
    while (!open_.empty()) {
      if (const std::size_t bytes = graph_.candidate_bytes() + open_.size() * sizeof(LazyEntry);
          bytes > budget_bytes)
        return bytes;
      const LazyEntry e = open_.top();
      open_.pop();
      if (!settle(e)) continue;
      if (e.node == g_) break;
      if (e.node < n_)
        expand_vertex(e);
      else
        expand_point(e);
    }
    return 0;
  }

  std::int64_t expanded() const { return expanded_; }
  std::int32_t vertex_count() const { return n_ + m_; }
  // The path found, repeated points dropped; empty when the goal was not reached.
  std::vector<Vec2> path() const {
    std::vector<Vec2> reversed, out;
    if (!closed_[g_]) return out;
    for (std::int32_t v = g_; v != -1; v = parent_[v]) reversed.push_back(point(v));
    for (auto it = reversed.rbegin(); it != reversed.rend(); ++it)
      if (out.empty() || !(out.back() == *it)) out.push_back(*it);
    return out;
  }

 private:
  static constexpr std::int32_t kUntested = LazyEntry::kUntested;

  Vec2 point(std::int32_t v) const {
    return v < n_ ? vertices_[v].p : v < s_ ? corners_[v - n_] : v == s_ ? start_ : goal_;
  }
  bool clear_of_added(Vec2 a, Vec2 b) {
    for (const Rect& r : added_) {
      ++stats_.added_tests;
      if (geom::segment_enters_open_rect(a, b, r)) return false;
    }
    return true;
  }
  void push(std::int32_t v, std::int32_t from, std::int32_t candidate, double gv) {
    if (!closed_[v]) open_.push({gv + geom::distance(point(v), goal_), gv, v, from, candidate});
  }

  // The map's verdict on the popped edge (cached in its graph), then the added rectangles'.
  bool settle(const LazyEntry& e) {
    if (closed_[e.node]) return false;
    if (e.parent >= 0) {
      const Vec2 a = point(e.parent), b = point(e.node);
      const bool on_map =
          e.candidate == kUntested
              ? graph_.visible(a, b)
              : graph_.candidate_visible(e.parent, static_cast<std::size_t>(e.candidate));
      if (!on_map || !clear_of_added(a, b)) return false;
    }
    closed_[e.node] = 1;
    parent_[e.node] = e.parent;
    ++expanded_;
    return true;
  }

  // A map vertex: its candidate edges, the added corners and the goal, where a shortest path
  // may bend around its own rectangle.
  void expand_vertex(const LazyEntry& e) {
    const Vec2 u = point(e.node), prev = point(e.parent);
    const auto& cands = graph_.candidates(e.node);
    stats_.base_candidates += static_cast<std::int64_t>(cands.size());
    for (std::size_t i = 0; i < cands.size(); ++i) {
      const std::int32_t to = cands[i].to;
      if (closed_[to] || inside_any(added_, vertices_[to].p) ||
          !graph_.taut(prev, e.node, vertices_[to].p))
        continue;
      push(to, e.node, static_cast<std::int32_t>(i), e.g + cands[i].length);
    }
    for (std::int32_t k = 0; k < m_; ++k)
      if (VisibilityGraph::tangent(vertices_[e.node], corners_[k] - u) &&
          graph_.taut(prev, e.node, corners_[k]))
        push(n_ + k, e.node, kUntested, e.g + geom::distance(u, corners_[k]));
    if (VisibilityGraph::tangent(vertices_[e.node], goal_ - u) && graph_.taut(prev, e.node, goal_))
      push(g_, e.node, kUntested, e.g + geom::distance(u, goal_));
  }

  // The start or an added corner: the map's vertices by the tangent ring scan, every other added
  // corner, and the goal.
  void expand_point(const LazyEntry& e) {
    const Vec2 u = point(e.node);
    from_point_.clear();
    graph_.candidates_from_point(u, from_point_);
    for (const GraphEdge& c : from_point_)
      if (!inside_any(added_, vertices_[c.to].p)) push(c.to, e.node, kUntested, e.g + c.length);
    for (std::int32_t k = 0; k < m_; ++k)
      if (n_ + k != e.node) push(n_ + k, e.node, kUntested, e.g + geom::distance(u, corners_[k]));
    push(g_, e.node, kUntested, e.g + geom::distance(u, goal_));
  }

  const VisibilityGraph& graph_;
  const std::vector<GraphVertex>& vertices_;
  const std::vector<Rect>& added_;
  const std::vector<Vec2> corners_;
  const Vec2 start_, goal_;
  const std::int32_t n_, m_, s_, g_;
  LazyOpenList open_;
  std::vector<char> closed_;
  std::vector<std::int32_t> parent_;
  std::vector<GraphEdge> from_point_;
  std::int64_t expanded_ = 0;
  OverlayStats& stats_;
};

// Where the query cannot start or end: blocked on the map, the goal in an added rectangle, or a
// start in one with no free way out. A start in one moves out to its nearest free boundary point.
std::optional<PlanStatus> usable_overlay_ends(const ObstacleMap& map,
                                              const std::vector<Rect>& added, Vec2& start,
                                              Vec2 goal, PlanResult& out) {
  if (!map.point_free(start)) return PlanStatus::kStartBlocked;
  if (!map.point_free(goal) || inside_any(added, goal)) return PlanStatus::kGoalBlocked;
  if (inside_any(added, start)) {
    const auto moved = out_of_added(map, added, start);
    if (!moved) return PlanStatus::kStartBlocked;
    start = *moved;
    out.start_snapped = true;
  }
  return std::nullopt;
}

}  // namespace

PlanResult plan_with_added(const VisibilityGraphPlanner& base, const std::vector<Rect>& added,
                           Vec2 start, Vec2 goal, OverlayStats* stats) {
  const auto t0 = std::chrono::steady_clock::now();
  const ObstacleMap& map = base.map();
  PlanResult out;
  OverlayStats local;
  if (const auto blocked = usable_overlay_ends(map, added, start, goal, out)) {
    out.status = *blocked;
    return out;
  }
  OverlaySearch search(base.graph(), added, free_corners(map, added), start, goal,
                       stats ? *stats : local);
  const std::size_t over_budget_bytes = search.run(base.input().search_budget_bytes);
  out.stats.expanded = search.expanded();
  out.stats.vertices = search.vertex_count();
  if (over_budget_bytes > 0) {
    out.status = PlanStatus::kSearchLimit;
    out.note = search_limit_note("vg (replanning round sensed obstacles)",
                                 base.input().search_budget_bytes, over_budget_bytes,
                                 "candidate edges and the queue");
  } else if (out.path = search.path(); out.path.empty()) {
    out.status = PlanStatus::kNoPath;
  } else {
    out.status = PlanStatus::kOk;
    out.length = geom::polyline_length(out.path);
  }
  out.stats.query_ms = util::ms_since(t0);
  return out;
}

}  // namespace plantsim::planner
