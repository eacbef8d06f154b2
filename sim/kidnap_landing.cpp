// Rejection sampling of a landing pose on the plant's free floor.
#include "sim/kidnap_landing.h"

#include <cmath>
#include <random>

#include "geometry/predicates.h"

namespace plantsim::sim {

std::optional<geom::Pose2> kidnap_landing(const worlds::World& plant, geom::Vec2 from, double min_m,
                                          double max_m, std::uint64_t seed) {
  constexpr double kMargin_m = 0.2;  // free floor around the robot's disk
  const double clear = plant.robot.radius_m + kMargin_m;
  std::mt19937_64 rng(seed ^ 0x6b69646e6170ULL);  // "kidnap": apart from the sensors' streams
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const geom::Rect charger = worlds::charger_body(plant).bounding_box();
  for (int draw = 0; draw < 500; ++draw) {
    const double d = min_m + (max_m - min_m) * unit(rng);
    const double direction = 2 * M_PI * unit(rng);
    const double yaw = geom::wrap_angle(2 * M_PI * unit(rng));
    const geom::Vec2 p = from + d * geom::Vec2{std::cos(direction), std::sin(direction)};
    const geom::Rect floor = plant.floor;
    if (p.x < floor.xmin + clear || p.x > floor.xmax - clear || p.y < floor.ymin + clear ||
        p.y > floor.ymax - clear)
      continue;
    bool free = !geom::in_closed_rect(charger.inflated(clear), p);
    for (const geom::Rect& r : plant.obstacles)
      free = free && !geom::in_closed_rect(r.inflated(clear), p);
    for (const geom::Rect& r : plant.unmapped)
      free = free && !geom::in_closed_rect(r.inflated(clear), p);
    if (free) return geom::Pose2{p.x, p.y, yaw};
  }
  return std::nullopt;
}

}  // namespace plantsim::sim
