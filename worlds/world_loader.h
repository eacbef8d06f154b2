// Reading worlds from files: plantsim's world JSON (schema in docs/world_format.md) and the
// plain benchmark worlds of shared/data/worlds (rects/start/goal; the goal becomes the
// charger). Every problem is reported as a WorldError naming the file and the field.
#pragma once

#include <string>

#include "worlds/world.h"
#include "worlds/world_error.h"

namespace plantsim::worlds {

/// Loads and validates a world file. Throws WorldError on any problem.
World load_world(const std::string& path);

/// Parses and validates world JSON text; `source` names it in messages.
World parse_world_json(const std::string& text, const std::string& source);

/// Checks a world for consistency (finite numbers, positive sizes, robot fits, start and
/// charger free of obstacles and inside the floor). Throws WorldError.
void validate_world(const World& world);

}  // namespace plantsim::worlds
