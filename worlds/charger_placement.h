// Choosing the docked heading for a charger given only as a point (the plain benchmark
// worlds): the heading whose charger body, staging pose and straight final approach are all
// clear of obstacles and walls, preferring to arrive facing away from the start.
#pragma once

#include <optional>

#include "worlds/world.h"

namespace plantsim::worlds {

/// Tries the eight compass headings; returns none when no heading leaves room to dock.
std::optional<double> choose_docking_heading(const World& world, Vec2 dock_point);

/// True when the charger body, staging pose and final approach of `world` are clear.
bool docking_area_clear(const World& world);

}  // namespace plantsim::worlds
