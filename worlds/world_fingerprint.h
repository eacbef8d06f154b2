// A world's content as one number: its geometry, robot, charger, actors and map mismatch, not
// its name or file. Batches draw each episode's start from it and the seed, so an episode is
// the same whatever the world's place in a scenario's list or the file it was read from.
#pragma once

#include <cstdint>

#include "worlds/world.h"

namespace plantsim::worlds {

std::uint64_t world_fingerprint(const World& world);

}  // namespace plantsim::worlds
