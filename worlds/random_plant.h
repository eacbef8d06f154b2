// Random plant worlds in the manner of shared/data/worlds/gen_world.py: n axis-aligned
// rectangles covering about `coverage` of the floor, any two at least `min_gap` apart (or,
// with overlap allowed, placed freely so that they merge), start near the left wall and the
// charger near the right one, both in free space. Deterministic for a given seed (its own
// generator: the same rules as the Python script, not the same bytes).
#pragma once

#include <cstdint>
#include <random>

#include "worlds/world.h"

namespace plantsim::worlds {

struct RandomPlantOptions {
  int rect_count = 50;
  std::uint64_t seed = 1;
  double width_m = 100.0;
  double height_m = 60.0;
  double coverage = 0.12;      ///< fraction of the floor the rectangles cover (before overlap)
  double min_gap_m = 0.7;      ///< between rectangles and to the walls, when not overlapping
  bool allow_overlap = false;  ///< place rectangles freely, so they may overlap and touch
};

/// A plant of `rect_count` rectangles with world_N1000's size of rectangle and density: its
/// 100 x 60 m floor grown with the count (benchmarks and tests at scale).
RandomPlantOptions as_dense_as_n1000(int rect_count, std::uint64_t seed);

/// Throws std::invalid_argument when the options are out of range or the rectangles cannot
/// be placed.
World random_plant(const RandomPlantOptions& options);

/// Places the start (near the left wall, x < min(6, width / 4)) and the charger (near the
/// right one) in free space with room to dock, as random_plant does, drawing from `rng`.
/// Throws std::invalid_argument when no such places exist.
void place_start_and_charger(World& w, std::mt19937_64& rng);

}  // namespace plantsim::worlds
