// A MovingAI grid map (.map) as a plantsim world: 1 m cells, every terrain but '.' and 'G' a
// blocked square (the any-angle rule), merged into rectangles; the robot and the clearance of
// the plain benchmark worlds (0.3 m inflation in all). Start and charger come from a query of a
// .scen file (cell centres; the charger faces whichever way leaves room to dock) or are given.
#pragma once

#include <optional>
#include <string>

#include "worlds/grid_map.h"
#include "worlds/world.h"

namespace plantsim::worlds {

/// The start and charger from `scen`'s query `query` (from 0), unless given. Throws WorldError
/// naming the file: no such query, a cell outside the map or blocked, no room for a charger.
World world_from_movingai(const std::string& map_path, const std::string& scen_path, int query,
                          std::optional<Pose2> start, std::optional<Pose2> charger);

}  // namespace plantsim::worlds
