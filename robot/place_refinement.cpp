// Pattern search on the likelihood field (see place_refinement.h).
#include "robot/place_refinement.h"

#include <algorithm>
#include <cmath>

namespace plantsim::robot {

geom::Pose2 refine_on_field(const LikelihoodField& field, const std::vector<geom::Vec2>& points,
                            geom::Pose2 start, double reach_m, double reach_rad, double cap_m) {
  const double cap2 = cap_m * cap_m;
  auto cost = [&](const geom::Pose2& x) {
    const double c = std::cos(x.yaw), s = std::sin(x.yaw);
    double sum = 0;
    for (const geom::Vec2& e : points) {
      const double d = field.distance({x.x + c * e.x - s * e.y, x.y + s * e.x + c * e.y});
      sum += std::min(d * d, cap2);
    }
    return sum;
  };
  geom::Pose2 best = start;
  double best_cost = cost(best);
  // Steps from a quarter of the reach down to a fiftieth of it: each round tries one step each
  // way along x, y and yaw and keeps any improvement, halving the steps when none helps.
  double step_m = 0.25 * reach_m, step_rad = 0.25 * reach_rad;
  for (int round = 0; round < 60 && step_m > 0.02 * reach_m; ++round) {
    bool improved = false;
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {1.0, -1.0}) {
        geom::Pose2 trial = best;
        if (axis == 0) trial.x += sign * step_m;
        if (axis == 1) trial.y += sign * step_m;
        if (axis == 2) trial.yaw = geom::wrap_angle(trial.yaw + sign * step_rad);
        if (std::fabs(trial.x - start.x) > reach_m || std::fabs(trial.y - start.y) > reach_m ||
            std::fabs(geom::wrap_angle(trial.yaw - start.yaw)) > reach_rad)
          continue;
        const double c = cost(trial);
        if (c < best_cost) {
          best_cost = c;
          best = trial;
          improved = true;
        }
      }
    if (!improved) {
      step_m *= 0.5;
      step_rad *= 0.5;
    }
  }
  return best;
}

}  // namespace plantsim::robot
