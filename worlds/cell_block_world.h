// Seed 004's experiment as generated work areas: the document's 40 x 20 m floor on a 2 m grid
// (20 x 10 cells), obstacles as blocks of whole cells (1-3 by 1-2) dropped at random until the
// given share of cells is blocked (the document "sets different obstacle shares to model
// different complexities" and regularises every obstacle to whole cells). The robot starts in
// the bottom-left cell; the charger stands on the west wall in the top-left cell; the 2 x 2
// cells at both keep free. Deterministic for a given seed.
#pragma once

#include <cstdint>

#include "worlds/world.h"

namespace plantsim::worlds {

struct CellBlockOptions {
  double blocked_share = 0.2;  ///< of the 200 cells, 0 to 0.5
  std::uint64_t seed = 1;
};

/// Throws std::invalid_argument for a share outside [0, 0.5].
World cell_block_world(const CellBlockOptions& options);

}  // namespace plantsim::worlds
