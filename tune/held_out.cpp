// The held-out check by content (see the header).
#include "tune/held_out.h"

#include <algorithm>
#include <cstdio>

#include "worlds/world_error.h"

namespace plantsim::tune {

void check_held_out(const batch::BatchSpec& tuning, const batch::ScenarioWorlds& tuning_worlds,
                    const batch::BatchSpec& validation,
                    const batch::ScenarioWorlds& validation_worlds) {
  const auto shared_seed = [&]() -> const std::uint64_t* {
    for (const std::uint64_t& s : validation.seeds)
      if (std::find(tuning.seeds.begin(), tuning.seeds.end(), s) != tuning.seeds.end()) return &s;
    return nullptr;
  }();
  if (!shared_seed) return;
  for (std::size_t v = 0; v < validation_worlds.contents.size(); ++v)
    for (std::size_t t = 0; t < tuning_worlds.contents.size(); ++t) {
      if (validation_worlds.contents[v] != tuning_worlds.contents[t]) continue;
      char fingerprint[17];
      std::snprintf(fingerprint, sizeof fingerprint, "%016llx",
                    static_cast<unsigned long long>(validation_worlds.contents[v]));
      const bool same_file = validation.world_files[v] == tuning.world_files[t];
      throw worlds::WorldError(
          validation.source, "tune.validation_worlds[" + std::to_string(v) + "]",
          "'" + validation.world_files[v] + "'" + (same_file ? " is" : " has the content of") +
              " the tuning world '" + tuning.world_files[t] + "' (content fingerprint " +
              fingerprint + ")" + ", and seed " + std::to_string(*shared_seed) +
              " is in both parts: validation episodes must be held out (choose other worlds "
              "or other validation_seeds)");
    }
}

}  // namespace plantsim::tune
