// Random starts of a batch (see the header).
#include "batch/random_start.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/predicates.h"
#include "util/fingerprint.h"

namespace plantsim::batch {

std::optional<geom::Pose2> random_start(const worlds::World& w, planner::Planner& vg,
                                        std::uint64_t seed, std::uint64_t world_content) {
  std::mt19937_64 rng(
      util::Fingerprint().add(world_content).add(seed).add(std::uint64_t{17}).value());
  std::uniform_real_distribution<double> ux(w.floor.xmin, w.floor.xmax),
      uy(w.floor.ymin, w.floor.ymax), yaw(-M_PI, M_PI);
  const geom::Vec2 staging = worlds::staging_pose(w).position();
  for (int attempt = 0; attempt < 2000; ++attempt) {
    const geom::Pose2 p{ux(rng), uy(rng), yaw(rng)};
    if (geom::distance(p.position(), w.charger.position()) < 2.0) continue;
    bool too_close = false;  // not starting against an actor's box
    for (const auto& m : w.moving) {
      const geom::Rect b = m.box_at(0.0);
      const double dx = std::max({b.xmin - p.x, 0.0, p.x - b.xmax}),
                   dy = std::max({b.ymin - p.y, 0.0, p.y - b.ymax});
      too_close |= std::hypot(dx, dy) < w.robot.radius_m + 1.0;
    }
    for (const geom::Rect& u : w.unmapped) {  // not inside (or against) a box the map lacks
      const double dx = std::max({u.xmin - p.x, 0.0, p.x - u.xmax}),
                   dy = std::max({u.ymin - p.y, 0.0, p.y - u.ymax});
      too_close |= std::hypot(dx, dy) < w.robot.radius_m + 0.3;
    }
    if (too_close) continue;
    if (vg.plan(p.position(), staging).status == planner::PlanStatus::kOk) return p;
  }
  return std::nullopt;
}

}  // namespace plantsim::batch
