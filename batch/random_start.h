// Random starts of a batch: where an episode of a given world and seed sets off.
#pragma once

#include <cstdint>
#include <optional>

#include "geometry/vec2.h"
#include "planner/planner.h"
#include "worlds/world.h"

namespace plantsim::batch {

/// A free start for this world and seed: uniform over the floor, outside inflated obstacles,
/// with a path to the staging pose (by `vg`), not right at the charger; the same for the same
/// world content and seed. None after 2000 tries.
std::optional<geom::Pose2> random_start(const worlds::World& w, planner::Planner& vg,
                                        std::uint64_t seed, std::uint64_t world_content);

}  // namespace plantsim::batch
