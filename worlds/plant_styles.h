// Generated plants of named styles, for testing on plants nobody tuned on: sparse (5 to 20 boxes
// on 100 x 60 m), dense (boxes over a quarter of the floor), racks (rows of long shelving with
// aisles and cross-aisles), corridors (blocks between corridors 1.2 to 2 m wide), yard (open
// ground with a few long walls) and mixed (buildings, machines and small clutter). Each style
// draws its own sizes from the seed; the start and charger are placed as random_plant places
// them. Deterministic for a given style and seed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "worlds/world.h"

namespace plantsim::worlds {

/// The style names, in the order they are documented.
const std::vector<std::string>& plant_style_names();

/// A plant of `style` (one of plant_style_names()) on a `width_m` x `height_m` floor.
/// Throws std::invalid_argument for an unknown style (naming the known ones) or a floor too
/// small for it.
World styled_plant(const std::string& style, std::uint64_t seed, double width_m = 100.0,
                   double height_m = 60.0);

}  // namespace plantsim::worlds
