// The driven length's lower bound (see the header).
#include "batch/shortest_possible.h"

#include <algorithm>
#include <cmath>

namespace plantsim::batch {

namespace {
// Box2D lets a resting contact overlap by up to its linear slop (0.005 m); twice that, so
// that no true position falls inside a grown box.
constexpr double kContactSlop_m = 0.01;
}  // namespace

planner::PlannerInput shortest_possible_input(const worlds::World& plant) {
  planner::PlannerInput in;
  in.floor = plant.floor;
  in.obstacles = plant.obstacles;
  in.obstacles.insert(in.obstacles.end(), plant.unmapped.begin(), plant.unmapped.end());
  const double inscribed = plant.robot.rectangular()
                               ? 0.5 * std::min(plant.robot.length_m, plant.robot.width_m)
                               : plant.robot.radius_m;
  in.inflation_m = std::max(0.0, inscribed - kContactSlop_m) / std::sqrt(2.0);
  in.corner_steps = 1;
  in.snap_to_free = false;  // a snapped end would no longer bound the path
  return in;
}

std::optional<double> shortest_possible_m(planner::Planner& bound, const geom::Pose2& start,
                                          const std::vector<episode::EpisodeResult::Carry>& carries,
                                          geom::Vec2 end) {
  double total = 0;
  geom::Vec2 from = start.position();
  auto leg = [&](geom::Vec2 to) {
    const planner::PlanResult p = bound.plan(from, to);
    if (p.status != planner::PlanStatus::kOk) return false;
    total += p.length;
    return true;
  };
  for (const episode::EpisodeResult::Carry& c : carries) {
    if (!leg(c.from.position())) return std::nullopt;
    from = c.to.position();
  }
  if (!leg(end)) return std::nullopt;
  return total;
}

}  // namespace plantsim::batch
