// Where a kidnap sets the robot down when its landing is drawn (the `kidnap` fault with a
// distance range): a random direction and distance from where it was lifted, a random heading,
// on free floor of the plant (clear of every obstacle, mapped or not, of the charger block and
// of the walls by the robot's radius and a margin). The plant's truth: the robot never sees it.
#pragma once

#include <cstdint>
#include <optional>

#include "geometry/vec2.h"
#include "worlds/world.h"

namespace plantsim::sim {

/// A free pose `min_m` to `max_m` from `from`, drawn with `seed`, or none when 500 draws found
/// no free floor there.
std::optional<geom::Pose2> kidnap_landing(const worlds::World& plant, geom::Vec2 from, double min_m,
                                          double max_m, std::uint64_t seed);

}  // namespace plantsim::sim
