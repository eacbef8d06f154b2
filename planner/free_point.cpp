// Candidate enumeration for the nearest free point.
#include "planner/free_point.h"

#include <algorithm>
#include <cmath>

#include "geometry/predicates.h"

namespace plantsim::planner {

std::optional<Vec2> nearest_free_point(const ObstacleMap& map, Vec2 p) {
  if (map.point_free(p)) return p;
  const Rect& f = map.free_floor();
  // Off the floor: the clamped point is the first candidate, and the search starts there.
  const Vec2 clamped{std::clamp(p.x, f.xmin, f.xmax), std::clamp(p.y, f.ymin, f.ymax)};
  const double limit = 2.0 * (f.width() + f.height()) + geom::distance(p, clamped);
  for (double radius = std::max(map.cell_size(), geom::distance(p, clamped)); radius <= 2 * limit;
       radius *= 2) {
    std::vector<double> xs = {p.x, f.xmin, f.xmax}, ys = {p.y, f.ymin, f.ymax};
    const Rect box{p.x - radius, p.y - radius, p.x + radius, p.y + radius};
    for (const Rect& r : map.rects()) {
      if (r.xmax < box.xmin || r.xmin > box.xmax || r.ymax < box.ymin || r.ymin > box.ymax)
        continue;
      xs.insert(xs.end(), {r.xmin, r.xmax});
      ys.insert(ys.end(), {r.ymin, r.ymax});
    }
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
    std::optional<Vec2> best;
    double best_d = radius;  // only answers within the radius are certain
    for (double x : xs)
      for (double y : ys) {
        const Vec2 c{x, y};
        const double d = geom::distance(p, c);
        if (d > best_d || !map.point_free(c) || map.is_pinch_point(c)) continue;
        if (!best || d < best_d ||
            (d == best_d && (c.x < best->x || (c.x == best->x && c.y < best->y)))) {
          best = c;
          best_d = d;
        }
      }
    if (best) return best;
  }
  return std::nullopt;
}

// Shared pre-checks; returns false and fills `out` when the query cannot proceed. With
// snapping on, a blocked end moves to the nearest free point and the result says so.
bool usable_endpoints(const ObstacleMap& map, bool snap, Vec2& start, Vec2& goal, PlanResult& out) {
  const auto usable = [&](Vec2& p, bool& snapped, PlanStatus blocked) {
    if (map.point_free(p)) return true;
    const auto moved = snap ? nearest_free_point(map, p) : std::nullopt;
    if (!moved) {
      out.status = blocked;
      return false;
    }
    p = *moved;
    snapped = true;
    return true;
  };
  return usable(start, out.start_snapped, PlanStatus::kStartBlocked) &&
         usable(goal, out.goal_snapped, PlanStatus::kGoalBlocked);
}

}  // namespace plantsim::planner
