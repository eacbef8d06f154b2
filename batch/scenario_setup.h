// A scenario made ready to run: its worlds loaded (names checked), its identity (the fingerprint
// that ties every record to the scenario that made it), and the episode settings per controller
// and fault. Shared by a batch, a merge and the replay of one episode.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "batch/batch_spec.h"
#include "episode/episode_config.h"
#include "worlds/world.h"

namespace plantsim::batch {

/// Which scenario a record belongs to: what makes its episodes (world contents, planners,
/// settings, faults, seeds, starts), not the file's name or the order of its lists' worlds.
struct ScenarioIdentity {
  std::string fingerprint;  ///< 16 hex digits
  std::int64_t episodes = 0;
  std::string file;  ///< absolute path, to draw a merge's figures again
};

ScenarioIdentity scenario_identity(const BatchSpec& spec,
                                   const std::vector<std::uint64_t>& world_contents,
                                   const std::vector<std::string>& world_names,
                                   std::int64_t episodes);

/// A scenario's worlds with their names and content fingerprints.
struct ScenarioWorlds {
  std::vector<worlds::World> worlds;
  std::vector<std::string> names;
  std::vector<std::uint64_t> contents;
};

/// Loads the worlds; refuses (worlds::WorldError) two of one name or two whose figure files would
/// be one (episode ids and figures name the world), and a gate rule naming a world the scenario
/// lacks.
ScenarioWorlds load_scenario_worlds(const BatchSpec& spec);

/// A charger offset must leave the mapped charger dockable on every world it is applied to.
void check_charger_offsets(const BatchSpec& spec, const std::vector<worlds::World>& worlds);

/// The episode settings, controller-major: index controller * faults + fault.
std::vector<episode::EpisodeConfig> episode_configs(const BatchSpec& spec);

}  // namespace plantsim::batch
