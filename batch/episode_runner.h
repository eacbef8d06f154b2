// Running one episode of a scenario, made the same way for the batch, for the failure gallery
// and for replaying one episode by its id: the plant with the episode's start and faults, the
// settings, the exact optimum, the planner.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "batch/batch_spec.h"
#include "batch/scenario_setup.h"
#include "episode/episode_config.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "worlds/world.h"

namespace plantsim::batch {

/// Everything one episode needs, made the same way for the batch and for replaying one of its
/// episodes: the plant with the episode's start and faults, the settings, the exact optimum.
class EpisodeRunner {
 public:
  EpisodeRunner(const BatchSpec& spec, const std::vector<worlds::World>& worlds,
                const std::vector<std::uint64_t>& contents,
                const std::vector<episode::EpisodeConfig>& configs,
                const episode::EpisodeSteering& steering = {})
      : spec_(spec), worlds_(worlds), contents_(contents), configs_(configs), steering_(steering) {}

  struct Run {
    worlds::World plant;
    episode::EpisodeConfig config;
    episode::EpisodeResult result;
    double optimal_m = 0;
    /// Docked episodes: the shortest path the centre could have driven (batch/shortest_possible.h).
    std::optional<double> shortest_possible_m;
  };

  /// Runs episode `e`: its plant (start, faults), settings and seed, and the exact optimum.
  Run run(const Episode& e);
  /// The same without running it (the result left empty): for an outside loop to run it.
  Run prepare(const Episode& e);

 private:
  // Planners are kept for the runner's life (their caches are not shared between threads). A
  // fault moving the mapped charger has its own (the charger's body is on the map).
  planner::Planner& planner_for(const worlds::World& w, std::size_t world, const std::string& name,
                                std::size_t fault) {
    const std::size_t key = spec_.faults[fault].charger_map_offset ? fault : spec_.faults.size();
    auto& p = planners_[{world, name, key}];
    if (!p) p = planner::make_planner(name, planner::planner_input(w, true));
    return *p;
  }

  /// The shortest possible drive of a docked episode (the plant's grown boxes; a world's planner
  /// kept while no unmapped box makes the episode's plant its own).
  std::optional<double> shortest_possible(const worlds::World& plant, std::size_t world,
                                          const episode::EpisodeResult& r);

  const BatchSpec& spec_;
  const std::vector<worlds::World>& worlds_;
  const std::vector<std::uint64_t>& contents_;
  const std::vector<episode::EpisodeConfig>& configs_;
  // A copy: the gallery and the replay pass the default, a temporary that a reference would
  // outlive.
  const episode::EpisodeSteering steering_;
  std::map<std::tuple<std::size_t, std::string, std::size_t>, std::unique_ptr<planner::Planner>>
      planners_;
  std::map<std::size_t, std::unique_ptr<planner::Planner>> bound_planners_;  // per world
};

/// One episode of a scenario run again on its own, exactly as the batch ran it (its start,
/// faults and seed come from the scenario and the episode's id).
struct ReplayedEpisode {
  std::string id;
  worlds::World plant;
  episode::EpisodeResult result;
  episode::EpisodeConfig config;
};
using FailedEpisode = ReplayedEpisode;

/// Failed episodes a batch report draws (replayed, each with its run figure).
inline constexpr std::size_t kGalleryEpisodes = 12;

/// Throws std::invalid_argument naming the scenario when it has no episode `id`.
ReplayedEpisode replay_batch_episode(const std::string& scenario_path, const std::string& id);

/// Replays up to `limit` failed episodes of the records for the report's failure gallery: one
/// of each failure reason first, then a second of each, ...
std::vector<FailedEpisode> failure_gallery(const std::vector<std::string>& lines,
                                           const BatchSpec& spec, const ScenarioWorlds& loaded,
                                           const std::vector<episode::EpisodeConfig>& configs,
                                           std::size_t limit);

}  // namespace plantsim::batch
