// A scenario made ready to run (see the header).
#include "batch/scenario_setup.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "episode/episode_config_json.h"
#include "util/fingerprint.h"
#include "worlds/known_keys.h"
#include "worlds/world_error.h"
#include "worlds/world_fingerprint.h"
#include "worlds/world_loader.h"

namespace plantsim::batch {
namespace {

std::string figure_stem(const std::string& world_name) {
  std::string stem = worlds::file_name_component(world_name);
  std::transform(stem.begin(), stem.end(), stem.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return stem;
}

}  // namespace

ScenarioIdentity scenario_identity(const BatchSpec& spec,
                                   const std::vector<std::uint64_t>& world_contents,
                                   const std::vector<std::string>& world_names,
                                   std::int64_t episodes) {
  util::Fingerprint f;
  f.add(std::string_view("plantsim scenario v1"));
  std::vector<std::string> worlds;
  for (std::size_t i = 0; i < world_contents.size(); ++i)
    worlds.push_back(world_names[i] + "#" + util::Fingerprint().add(world_contents[i]).hex());
  std::sort(worlds.begin(), worlds.end());
  for (const std::string& w : worlds) f.add(w);
  for (const std::string& p : spec.planners) f.add(p);
  for (const NamedConfig& c : spec.controllers) f.add(c.name).add(c.json);
  for (const FaultSetting& x : spec.faults) {
    f.add(x.name).add(x.json).add(
        static_cast<std::uint64_t>(x.crossing_obstacle * 4 + x.crossing_final_approach * 2));
    f.add(static_cast<std::uint64_t>(x.unmapped_obstacles));
    if (x.standing_at_dock_s > 0)
      f.add(std::string_view("standing_at_dock_s")).add(x.standing_at_dock_s);
    if (x.charger_map_offset)
      f.add(x.charger_map_offset->x).add(x.charger_map_offset->y).add(x.charger_map_offset->yaw);
    if (const auto& k = x.random_kidnap)
      f.add(std::string_view("random_kidnap"))
          .add(k->after_min_s)
          .add(k->after_max_s)
          .add(k->distance_min_m)
          .add(k->distance_max_m);
  }
  for (std::uint64_t seed : spec.seeds) f.add(seed);
  f.add(static_cast<std::uint64_t>(spec.random_starts));
  std::error_code ec;
  return {f.hex(), episodes,
          std::filesystem::absolute(spec.source, ec).lexically_normal().string()};
}

ScenarioWorlds load_scenario_worlds(const BatchSpec& spec) {
  ScenarioWorlds s;
  for (std::size_t i = 0; i < spec.world_files.size(); ++i) {
    s.worlds.push_back(worlds::load_world(spec.world_files[i]));
    s.names.push_back(s.worlds.back().name);
    s.contents.push_back(worlds::world_fingerprint(s.worlds.back()));
    for (std::size_t k = 0; k < i; ++k) {
      if (s.names[k] == s.names[i])
        throw worlds::WorldError(
            spec.source, "worlds[" + std::to_string(i) + "]",
            "a second world named '" + s.names[i] + "' (episode ids name the world; rename one)");
      // Figures are named after the world's file-safe name, on file systems that may ignore case.
      if (figure_stem(s.names[k]) == figure_stem(s.names[i]))
        throw worlds::WorldError(spec.source, "worlds[" + std::to_string(i) + "]",
                                 "worlds named '" + s.names[k] + "' and '" + s.names[i] +
                                     "' would share figure files (paths_" +
                                     worlds::file_name_component(s.names[i]) + ".png); rename one");
    }
  }
  for (std::size_t i = 0; i < spec.gate.rules.size(); ++i)
    if (const std::string& w = spec.gate.rules[i].world;
        !w.empty() && std::find(s.names.begin(), s.names.end(), w) == s.names.end())
      throw worlds::WorldError(
          spec.source, "gate.configurations[" + std::to_string(i) + "].world",
          "'" + w + "' is not one of the scenario's worlds: the rule would judge nothing");
  return s;
}

void check_charger_offsets(const BatchSpec& spec, const std::vector<worlds::World>& worlds) {
  for (const FaultSetting& f : spec.faults) {
    if (!f.charger_map_offset) continue;
    for (worlds::World w : worlds) {
      w.charger_map_offset = *f.charger_map_offset;
      try {
        worlds::validate_world(w);
      } catch (const worlds::WorldError& e) {
        throw worlds::WorldError(spec.source, "faults." + f.name + ".charger_map_offset",
                                 "on " + w.name + ": " + e.what());
      }
    }
  }
}

std::vector<episode::EpisodeConfig> episode_configs(const BatchSpec& spec) {
  std::vector<episode::EpisodeConfig> configs;  // controller x fault
  for (const auto& c : spec.controllers)
    for (const auto& f : spec.faults)
      configs.push_back(episode::parse_episode_config(
          f.json, spec.source, episode::parse_episode_config(c.json, spec.source)));
  return configs;
}

}  // namespace plantsim::batch
