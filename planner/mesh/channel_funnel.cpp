// The funnel: an apex (the last bend), and the ends of the portals that bound the directions
// still open from it on the right and on the left. Each portal in turn narrows it; an end that
// would cross the other side makes that side's end the next bend, and the scan goes on from
// the portal that end belongs to.
#include "planner/mesh/channel_funnel.h"

#include <cmath>
#include <cstddef>

namespace plantsim::planner {
namespace {

// How far q lies left of the line from a through p (negative: right), as a length.
double side(Vec2 a, Vec2 p, Vec2 q) {
  const Vec2 u = p - a, v = q - a;
  return (u.x * v.y - u.y * v.x) / std::sqrt(u.x * u.x + u.y * u.y);
}

bool near(Vec2 a, Vec2 b, double tolerance) {
  return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) <= tolerance * tolerance;
}

}  // namespace

std::vector<Vec2> funnel_path(Vec2 start, const std::vector<Portal>& portals, Vec2 goal,
                              double tolerance) {
  std::vector<Vec2> path{start};
  Vec2 apex = start, left = start, right = start;
  std::ptrdiff_t left_at = -1,
                 right_at = -1;  // the portal each side's end came from (-1: the start)
  // How far q lies left of the side from the apex through p; nothing when p is the apex (the
  // side not drawn yet, or drawn from a portal that ends at the apex).
  const auto beside = [&](Vec2 p, Vec2 q) {
    return near(apex, p, tolerance) ? 0.0 : side(apex, p, q);
  };
  const auto bend = [&](Vec2 at) {
    if (!near(path.back(), at, tolerance)) path.push_back(at);
    apex = left = right = at;
  };
  const auto count = static_cast<std::ptrdiff_t>(portals.size());
  for (std::ptrdiff_t i = 0; i <= count; ++i) {
    const Vec2 l = i < count ? portals[i].left : goal, r = i < count ? portals[i].right : goal;
    // An end on the other side's line (the funnel closed to one ray) still narrows it: the
    // path runs along that ray past both ends and bends at whichever the next portals turn it
    // round. (Bending there at once would bend at the farther one, a detour.)
    if (beside(right, r) >= -tolerance) {  // r narrows the funnel on the right
      if (near(apex, right, tolerance) || beside(left, r) <= tolerance) {
        right = r, right_at = i;
      } else {  // r crosses the left side: the path bends at the left end
        bend(left);
        i = right_at = left_at;
        continue;
      }
    }
    if (beside(left, l) <= tolerance) {  // l narrows it on the left
      if (near(apex, left, tolerance) || beside(right, l) >= -tolerance) {
        left = l, left_at = i;
      } else {  // l crosses the right side: the path bends at the right end
        bend(right);
        i = left_at = right_at;
        continue;
      }
    }
  }
  if (!near(path.back(), goal, tolerance) || path.size() == 1) path.push_back(goal);
  return path;
}

}  // namespace plantsim::planner
