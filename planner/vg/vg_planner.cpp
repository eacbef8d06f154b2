// Visibility-graph planners: the improved one (reduced graph, lazy edges, A*) and the
// traditional one (all corners, all pairs, Dijkstra).
#include "planner/vg/vg_planner.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <tuple>

#include "geometry/polyline.h"
#include "planner/astar.h"
#include "planner/free_point.h"
#include "planner/inflation.h"
#include "planner/search_budget.h"
#include "planner/vg/lazy_entry.h"
#include "planner/vg/vg_overlay.h"
#include "util/stopwatch.h"

namespace plantsim::planner {
namespace {

void fill_path(const SearchResult& found, const std::vector<Vec2>& points, PlanResult& out) {
  if (!found.found) {
    out.status = PlanStatus::kNoPath;
    return;
  }
  out.status = PlanStatus::kOk;
  for (std::int32_t n : found.nodes) {
    const Vec2 p = points[n];
    if (out.path.empty() || !(out.path.back() == p)) out.path.push_back(p);
  }
  out.length = geom::polyline_length(out.path);
}

}  // namespace

VisibilityGraphPlanner::VisibilityGraphPlanner(const PlannerInput& input)
    : build_start_(std::chrono::steady_clock::now()),
      input_(input),
      map_(inflate(input.obstacles, input.inflation_m, input.corner_steps), input.floor,
           input.inflation_m),
      graph_(map_),
      snap_(input.snap_to_free) {
  build_ms_ = util::ms_since(build_start_);
}

VisibilityGraphPlanner::VisibilityGraphPlanner(const PlannerInput& input,
                                               const VisibilityGraphPlanner& base,
                                               const std::vector<Rect>& changed)
    : build_start_(std::chrono::steady_clock::now()),
      input_(input),
      map_(inflate(input.obstacles, input.inflation_m, input.corner_steps), input.floor,
           input.inflation_m),
      graph_(map_, base.graph_, changed),
      snap_(input.snap_to_free) {
  build_ms_ = util::ms_since(build_start_);
}

std::unique_ptr<VisibilityGraphPlanner> VisibilityGraphPlanner::with_changes(
    const std::vector<Rect>& added, const std::vector<std::size_t>& removed) const {
  PlannerInput next = input_;
  std::vector<Rect> changed_raw = added;
  std::vector<char> drop(input_.obstacles.size(), 0);
  for (std::size_t i : removed) {
    if (i >= drop.size())
      throw std::out_of_range("vg: obstacle " + std::to_string(i) + " to remove; the world has " +
                              std::to_string(drop.size()));
    drop[i] = 1;
    changed_raw.push_back(input_.obstacles[i]);
  }
  next.obstacles.clear();
  for (std::size_t i = 0; i < input_.obstacles.size(); ++i)
    if (!drop[i]) next.obstacles.push_back(input_.obstacles[i]);
  next.obstacles.insert(next.obstacles.end(), added.begin(), added.end());
  const std::vector<Rect> changed = inflate(changed_raw, input_.inflation_m, input_.corner_steps);
  return std::unique_ptr<VisibilityGraphPlanner>(new VisibilityGraphPlanner(next, *this, changed));
}

PlanResult VisibilityGraphPlanner::plan(Vec2 start, Vec2 goal) {
  const auto t0 = std::chrono::steady_clock::now();
  PlanResult out;
  if (usable_endpoints(map_, snap_, start, goal, out)) {
    const SearchResult found = lazy_astar(start, goal);
    const auto& vertices = graph_.vertices();
    std::vector<Vec2> points;
    points.reserve(vertices.size() + 2);
    for (const auto& v : vertices) points.push_back(v.p);
    points.push_back(start);
    points.push_back(goal);
    fill_path(found, points, out);
    if (found.over_budget_bytes > 0) {
      out.status = PlanStatus::kSearchLimit;
      out.note = search_limit_note(name(), input_.search_budget_bytes, found.over_budget_bytes,
                                   "candidate edges and the queue");
    }
    out.stats.expanded = found.stats.expanded;
  }
  out.stats.build_ms = build_ms_;
  out.stats.query_ms = util::ms_since(t0);
  out.stats.vertices = static_cast<std::int64_t>(graph_.vertices().size());
  out.stats.edges = graph_.edges_found();
  out.stats.segment_tests = graph_.segment_tests();
  return out;
}

// A* with lazy edge evaluation: every candidate edge out of an expanded node is pushed
// untested, and its visibility is tested only when it is popped. With a consistent
// heuristic the first valid pop of a node carries its optimal cost, and candidates whose
// f exceeds the goal's are never tested at all.
namespace {

// One query's A* state over the graph's vertices and the two query points (start n, goal n + 1).
class LazySearch {
 public:
  LazySearch(const VisibilityGraph& graph, std::vector<std::uint16_t>& expansions, Vec2 start,
             Vec2 goal)
      : graph_(graph),
        vertices_(graph.vertices()),
        expansions_(expansions),
        start_(start),
        goal_(goal),
        s_(static_cast<std::int32_t>(vertices_.size())),
        g_(s_ + 1),
        closed_(s_ + 2, 0),
        parent_(s_ + 2, -1),
        cost_(s_ + 2, 0.0),
        best_known_(s_ + 2, std::numeric_limits<double>::infinity()) {
    expansions_.resize(vertices_.size(), 0);
    open_.push({geom::distance(start, goal), 0.0, s_, -1, kUntested});
  }

  SearchResult run(std::size_t budget_bytes) {
    while (!open_.empty()) {
      // The graph kept across queries counts too: it is what this query's candidates grow.
      if (const std::size_t bytes = graph_.candidate_bytes() + open_.size() * sizeof(Entry);
          bytes > budget_bytes) {
        result_.over_budget_bytes = bytes;
        break;
      }
      const Entry e = open_.top();
      open_.pop();
      if (!settle(e)) continue;
      if (e.node == g_) break;
      if (e.node == s_)
        expand_start();
      else
        expand(e);
    }
    if (closed_[g_]) {
      result_.found = true;
      result_.cost = cost_[g_];
      for (std::int32_t v = g_; v != -1; v = parent_[v]) result_.nodes.push_back(v);
      std::reverse(result_.nodes.begin(), result_.nodes.end());
    }
    return result_;
  }

 private:
  using Entry = LazyEntry;
  static constexpr std::int32_t kUntested = LazyEntry::kUntested;

  Vec2 point(std::int32_t v) const { return v == s_ ? start_ : v == g_ ? goal_ : vertices_[v].p; }

  // The cheapest cost pushed along an edge known to be visible (from a resolved vertex): a
  // later, dearer push can never be the one popped first, so it is not pushed. Equal costs are
  // still pushed, so that ties resolve exactly as before.
  void push(std::int32_t v, std::int32_t from, std::int32_t candidate, double gv,
            bool known_visible) {
    if (closed_[v] || gv > best_known_[v]) return;
    if (known_visible) best_known_[v] = std::min(best_known_[v], gv);
    open_.push({gv + geom::distance(point(v), goal_), gv, v, from, candidate});
    ++result_.stats.pushed;
  }

  // The edge an entry was pushed along is tested now, when popped; true if it closed the node.
  bool settle(const Entry& e) {
    if (closed_[e.node]) return false;
    if (e.parent >= 0) {
      const bool ok =
          e.candidate == kUntested
              ? graph_.visible(point(e.parent), point(e.node))
              : graph_.candidate_visible(e.parent, static_cast<std::size_t>(e.candidate));
      if (!ok) return false;
    }
    closed_[e.node] = 1;
    parent_[e.node] = e.parent;
    cost_[e.node] = e.g;
    ++result_.stats.expanded;
    return true;
  }

  void expand_start() {
    graph_.candidates_from_point(start_, from_start_);
    for (const GraphEdge& c : from_start_) push(c.to, s_, kUntested, c.length, false);
    push(g_, s_, kUntested, geom::distance(start_, goal_), false);
  }

  void expand(const Entry& e) {
    // A vertex met again in a later search is worth resolving to its exact edges.
    if (expansions_[e.node] < 2 && ++expansions_[e.node] == 2) graph_.resolve(e.node);
    const auto& cands = graph_.candidates(e.node);
    const bool exact = graph_.resolved(e.node);
    const Vec2 u = point(e.node), prev = point(e.parent);
    for (std::size_t i = 0; i < cands.size(); ++i) {
      const std::int32_t w = cands[i].to;
      const double gw = e.g + cands[i].length;
      if (closed_[w] || gw > best_known_[w] || !graph_.taut(prev, e.node, vertices_[w].p)) continue;
      push(w, e.node, static_cast<std::int32_t>(i), gw, exact);
    }
    if (VisibilityGraph::tangent(vertices_[e.node], goal_ - u) && graph_.taut(prev, e.node, goal_))
      push(g_, e.node, kUntested, e.g + geom::distance(u, goal_), false);
  }

  const VisibilityGraph& graph_;
  const std::vector<GraphVertex>& vertices_;
  std::vector<std::uint16_t>& expansions_;  // per vertex, across queries
  const Vec2 start_, goal_;
  const std::int32_t s_, g_;
  LazyOpenList open_;
  std::vector<char> closed_;
  std::vector<std::int32_t> parent_;
  std::vector<double> cost_;
  std::vector<double> best_known_;
  std::vector<GraphEdge> from_start_;
  SearchResult result_;
};

}  // namespace

SearchResult VisibilityGraphPlanner::lazy_astar(Vec2 start, Vec2 goal) const {
  return LazySearch(graph_, expansions_, start, goal).run(input_.search_budget_bytes);
}

std::vector<std::pair<Vec2, Vec2>> VisibilityGraphPlanner::graph_edges() const {
  // The whole reduced graph (every vertex resolved), not just what searches have touched.
  for (std::int32_t v = 0; v < static_cast<std::int32_t>(graph_.vertices().size()); ++v)
    if (!graph_.resolved(v)) graph_.resolve(v);
  std::vector<std::pair<Vec2, Vec2>> out;
  for (const auto& [a, b] : graph_.visible_edges())
    out.emplace_back(graph_.vertices()[a].p, graph_.vertices()[b].p);
  return out;
}

std::vector<std::pair<Vec2, Vec2>> TraditionalVisibilityPlanner::graph_edges() const {
  std::vector<std::pair<Vec2, Vec2>> out;
  for (std::size_t a = 0; a < adjacency_.size(); ++a)
    for (const GraphEdge& e : adjacency_[a])
      if (static_cast<std::size_t>(e.to) > a) out.emplace_back(corners_[a], corners_[e.to]);
  return out;
}

TraditionalVisibilityPlanner::TraditionalVisibilityPlanner(const PlannerInput& input)
    : map_(inflate(input.obstacles, input.inflation_m, input.corner_steps), input.floor,
           input.inflation_m),
      snap_(input.snap_to_free) {
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < map_.obstacle_count(); ++i) {
    const Rect& r = map_.rects()[i];
    for (Vec2 c :
         {Vec2{r.xmin, r.ymin}, Vec2{r.xmax, r.ymin}, Vec2{r.xmax, r.ymax}, Vec2{r.xmin, r.ymax}})
      // A pinch point is never a bend of a valid path: both its edges would have to lie in
      // one free quadrant (no shortcut needed), or cross between the two (not allowed).
      if (map_.point_free(c) && !map_.is_pinch_point(c)) corners_.push_back(c);
  }
  adjacency_.resize(corners_.size());
  for (std::size_t a = 0; a < corners_.size(); ++a)
    for (std::size_t b = a + 1; b < corners_.size(); ++b) {
      ++segment_tests_;
      if (!map_.segment_free(corners_[a], corners_[b])) continue;
      const double len = geom::distance(corners_[a], corners_[b]);
      adjacency_[a].push_back({static_cast<std::int32_t>(b), len});
      adjacency_[b].push_back({static_cast<std::int32_t>(a), len});
      edges_ += 1;
    }
  build_ms_ = util::ms_since(t0);
}

PlanResult TraditionalVisibilityPlanner::plan(Vec2 start, Vec2 goal) {
  const auto t0 = std::chrono::steady_clock::now();
  PlanResult out;
  if (usable_endpoints(map_, snap_, start, goal, out)) {
    const auto n = static_cast<std::int32_t>(corners_.size());
    const std::int32_t s = n, g = n + 1;
    std::vector<Vec2> points = corners_;
    points.push_back(start);
    points.push_back(goal);
    // Start and goal joined to every visible corner, as the traditional method does.
    std::vector<GraphEdge> from_start, to_goal;
    for (std::int32_t w = 0; w < n; ++w) {
      if (map_.segment_free(start, corners_[w]))
        from_start.push_back({w, geom::distance(start, corners_[w])});
      if (map_.segment_free(corners_[w], goal))
        to_goal.push_back({w, geom::distance(corners_[w], goal)});
    }
    std::vector<double> goal_edge(n, -1.0);
    for (const auto& e : to_goal) goal_edge[e.to] = e.length;
    const bool direct = map_.segment_free(start, goal);
    const SearchResult found = best_first_search(
        n + 2, s, g, [](std::int32_t) { return 0.0; },
        [&](std::int32_t u, auto&& emit) {
          if (u == s) {
            for (const auto& e : from_start) emit(e.to, e.length);
            if (direct) emit(g, geom::distance(start, goal));
            return;
          }
          for (const GraphEdge& e : adjacency_[u]) emit(e.to, e.length);
          if (goal_edge[u] >= 0) emit(g, goal_edge[u]);
        });
    fill_path(found, points, out);
    out.stats.expanded = found.stats.expanded;
  }
  out.stats.build_ms = build_ms_;
  out.stats.query_ms = util::ms_since(t0);
  out.stats.vertices = static_cast<std::int64_t>(corners_.size());
  out.stats.edges = edges_;
  out.stats.segment_tests = segment_tests_;
  return out;
}

}  // namespace plantsim::planner

namespace plantsim::planner {

std::optional<PlanResult> VisibilityGraphPlanner::plan_around_added(
    const std::vector<Rect>& added_grown, Vec2 start, Vec2 goal) const {
  return plan_with_added(*this, added_grown, start, goal);
}

}  // namespace plantsim::planner
