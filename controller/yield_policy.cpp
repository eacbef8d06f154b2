// Giving way: threats within the horizon, and bystanders beside the approach.
#include "controller/yield_policy.h"

#include <algorithm>

namespace plantsim::controller {

bool threatened(const YieldParams& p, geom::Vec2 position, double radius_m,
                const std::vector<MovingBox>& boxes) {
  return position_threatened(position, radius_m, boxes, p.yield_horizon_s);
}

bool threatened_by_movers(const YieldParams& p, geom::Vec2 position, double radius_m,
                          const std::vector<MovingBox>& boxes) {
  std::vector<MovingBox> movers;
  for (const MovingBox& b : boxes)
    if (geom::norm(b.velocity) > 0.2) movers.push_back(b);
  return !movers.empty() && threatened(p, position, radius_m, movers);
}

bool bystander_near_corridor(const YieldParams& p, geom::Vec2 from, geom::Vec2 to,
                             geom::Vec2 charger_at, double clearance_m,
                             const std::vector<MovingBox>& boxes) {
  const double near = clearance_m + p.bystander_reach_m;
  for (const MovingBox& b : boxes) {
    if (distance_to_box(charger_at, b.box) <= 0.25) continue;
    if (std::max(b.box.width(), b.box.height()) > p.bystander_max_size_m) continue;
    if (segment_distance_to_box(from, to, b.box) < near) return true;
  }
  return false;
}

}  // namespace plantsim::controller
