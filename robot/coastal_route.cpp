// The coastal route: A* over candidate turns (the grown obstacles' corners and points along the
// edge of every surface's sight), each leg costing its length plus its blind stretches' cost.
// Every candidate but the start is in sight of a surface, so a leg's blind stretches are its own
// and the cost adds up along the route.
#include "robot/coastal_route.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "geometry/clearance.h"
#include "geometry/predicates.h"
#include "planner/planner.h"

namespace plantsim::robot {
namespace {

using geom::Rect;
using geom::Vec2;

/// The map as the route sees it.
struct Coast {
  std::vector<Rect> surfaces;  ///< what a scan can match: the map's boxes, the charger, the walls
  std::vector<Rect> blocked;   ///< grown by the planner's inflation
  Rect free;                   ///< the floor less the inflation along its walls
  double sight_m = 0;
  double blind_scale_m = 1;
};

Coast coast_of(const worlds::World& map, double lidar_range_m, const CoastalParams& params,
               const std::vector<Rect>& blocked) {
  const planner::PlannerInput in = planner::planner_input(map, true);
  Coast c;
  c.surfaces = in.obstacles;
  for (const Rect& wall : geom::surrounding_walls(in.floor, 1.0)) c.surfaces.push_back(wall);
  for (const Rect& r : in.obstacles) c.blocked.push_back(r.inflated(in.inflation_m));
  c.blocked.insert(c.blocked.end(), blocked.begin(), blocked.end());
  c.free = in.floor.inflated(-in.inflation_m);
  c.sight_m = params.sight_fraction * lidar_range_m;
  c.blind_scale_m = params.blind_scale_m;
  return c;
}

/// The blind parts of segment [p, q] as parameter intervals, in order.
std::vector<std::pair<double, double>> blind_spans(const Coast& c, Vec2 p, Vec2 q) {
  std::vector<std::pair<double, double>> seen;
  for (const Rect& s : c.surfaces)
    if (auto span = geom::segment_span_within(p, q, s, c.sight_m)) seen.push_back(*span);
  std::sort(seen.begin(), seen.end());
  std::vector<std::pair<double, double>> blind;
  double from = 0;
  for (const auto& [lo, hi] : seen) {
    if (lo > from) blind.emplace_back(from, lo);
    from = std::max(from, hi);
  }
  if (from < 1) blind.emplace_back(from, 1.0);
  return blind;
}

Blindness blindness_of(const Coast& c, const std::vector<Vec2>& path) {
  Blindness b;
  double running = 0;  // a blind stretch may go on over a turn
  auto close = [&] {
    b.longest_m = std::max(b.longest_m, running);
    b.total_m += running;
    b.cost_m += running * running / c.blind_scale_m;
    running = 0;
  };
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double length = geom::distance(path[i], path[i + 1]);
    const auto spans = blind_spans(c, path[i], path[i + 1]);
    if (length > 0 && spans.empty()) close();
    for (const auto& [lo, hi] : spans) {
      if (lo > 0) close();
      running += (hi - lo) * length;
      if (hi < 1) close();
    }
  }
  close();
  return b;
}

double leg_cost(const Coast& c, Vec2 p, Vec2 q) {
  const double length = geom::distance(p, q);
  double cost = length;
  for (const auto& [lo, hi] : blind_spans(c, p, q)) {
    const double blind = (hi - lo) * length;
    cost += blind * blind / c.blind_scale_m;
  }
  return cost;
}

bool usable(const Coast& c, Vec2 p) {
  if (!geom::in_closed_rect(c.free, p)) return false;
  return std::none_of(c.blocked.begin(), c.blocked.end(),
                      [&](const Rect& r) { return geom::in_open_rect(r, p); });
}

bool leg_clear(const Coast& c, Vec2 p, Vec2 q) {
  return std::none_of(c.blocked.begin(), c.blocked.end(),
                      [&](const Rect& r) { return geom::segment_enters_open_rect(p, q, r); });
}

/// Points on the edge of a surface's sight (just inside it), spaced at most `spacing` apart
/// along its straight sides, one on each rounded corner.
void add_sight_edge(const Rect& s, double sight_m, double spacing, std::vector<Vec2>& out) {
  const double d = 0.98 * sight_m;
  auto side = [&](Vec2 a, Vec2 b) {
    const int n = std::max(1, static_cast<int>(std::ceil(geom::distance(a, b) / spacing)));
    for (int k = 0; k <= n; ++k) out.push_back(a + (static_cast<double>(k) / n) * (b - a));
  };
  side({s.xmin, s.ymin - d}, {s.xmax, s.ymin - d});
  side({s.xmax + d, s.ymin}, {s.xmax + d, s.ymax});
  side({s.xmax, s.ymax + d}, {s.xmin, s.ymax + d});
  side({s.xmin - d, s.ymax}, {s.xmin - d, s.ymin});
  const double r = d / std::sqrt(2.0);
  for (Vec2 k : {Vec2{s.xmin - r, s.ymin - r}, Vec2{s.xmax + r, s.ymin - r},
                 Vec2{s.xmax + r, s.ymax + r}, Vec2{s.xmin - r, s.ymax + r}})
    out.push_back(k);
}

std::vector<Vec2> candidates(const Coast& c, Vec2 start, Vec2 goal, double spacing) {
  std::vector<Vec2> all{start, goal};
  constexpr double kOff = 1e-6;  // corners just outside their box, never on its boundary
  for (const Rect& r : c.blocked)
    for (Vec2 k : {Vec2{r.xmin - kOff, r.ymin - kOff}, Vec2{r.xmax + kOff, r.ymin - kOff},
                   Vec2{r.xmax + kOff, r.ymax + kOff}, Vec2{r.xmin - kOff, r.ymax + kOff}})
      all.push_back(k);
  for (const Rect& s : c.surfaces) add_sight_edge(s, c.sight_m, spacing, all);
  std::vector<Vec2> kept{start, goal};
  for (std::size_t i = 2; i < all.size(); ++i)
    if (usable(c, all[i])) kept.push_back(all[i]);
  return kept;
}

/// A* from nodes[0] to nodes[1], the legs evaluated as they are reached.
std::vector<Vec2> cheapest_route(const Coast& c, const std::vector<Vec2>& nodes) {
  const std::size_t n = nodes.size();
  std::vector<double> g(n, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> from(n, n);
  std::vector<bool> done(n, false);
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  g[0] = 0;
  open.emplace(geom::distance(nodes[0], nodes[1]), 0);
  while (!open.empty()) {
    const std::size_t u = open.top().second;
    open.pop();
    if (done[u]) continue;
    done[u] = true;
    if (u == 1) break;
    for (std::size_t v = 1; v < n; ++v) {
      if (done[v] || !leg_clear(c, nodes[u], nodes[v])) continue;
      const double cost = g[u] + leg_cost(c, nodes[u], nodes[v]);
      if (cost < g[v]) {
        g[v] = cost;
        from[v] = u;
        open.emplace(cost + geom::distance(nodes[v], nodes[1]), v);
      }
    }
  }
  if (!done[1]) return {};
  std::vector<Vec2> route;
  for (std::size_t k = 1; k != n; k = from[k]) route.push_back(nodes[k]);
  std::reverse(route.begin(), route.end());
  return route;
}

double length_of(const std::vector<Vec2>& path) {
  double sum = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) sum += geom::distance(path[i], path[i + 1]);
  return sum;
}

}  // namespace

Blindness blindness(const worlds::World& map, const std::vector<Vec2>& path, double lidar_range_m,
                    const CoastalParams& params) {
  return blindness_of(coast_of(map, lidar_range_m, params, {}), path);
}

std::vector<Vec2> coastal_route(const worlds::World& map, std::vector<Vec2> path,
                                double lidar_range_m, const CoastalParams& params,
                                const std::vector<Rect>& blocked) {
  if (!params.enabled || !(lidar_range_m > 0) || path.size() < 2) return path;
  const Coast c = coast_of(map, lidar_range_m, params, blocked);
  const Blindness now = blindness_of(c, path);
  if (now.longest_m <= params.activate_blind_m) return path;
  if (!usable(c, path.front()) || !usable(c, path.back())) return path;
  const std::vector<Vec2> nodes = candidates(c, path.front(), path.back(), params.node_spacing_m);
  if (nodes.size() > static_cast<std::size_t>(params.max_nodes)) return path;
  std::vector<Vec2> route = cheapest_route(c, nodes);
  if (route.empty()) return path;
  route.insert(route.begin(), path.front());
  const double route_cost = length_of(route) + blindness_of(c, route).cost_m;
  return route_cost < length_of(path) + now.cost_m ? route : path;
}

}  // namespace plantsim::robot
