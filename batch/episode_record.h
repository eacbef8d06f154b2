// One episode's line of episodes.jsonl: its id and place in the scenario, its settings' names,
// the metrics of its result, the exact optimum, its driven path thinned for the report.
#pragma once

#include <optional>
#include <string>

#include "batch/batch_spec.h"
#include "batch/scenario_setup.h"
#include "episode/episode_result.h"
#include "worlds/world.h"

namespace plantsim::batch {

/// The episode's key: its scenario's fingerprint and its id as one hash, written in its record
/// so that a merge without the scenario file still refuses a record of another run (or one
/// edited) standing in for a missing episode.
std::string episode_key(const std::string& scenario_fingerprint, const std::string& id);

/// The JSON record (one line, no newline) of episode `e` run on `plant` with result `r`;
/// `optimal_m` is the exact shortest path to the staging pose (the planners' yardstick);
/// `shortest_possible_m` the driven length's lower bound (docked episodes;
/// batch/shortest_possible.h).
std::string record_line(const Episode& e, const BatchSpec& spec, const ScenarioIdentity& scenario,
                        const worlds::World& plant, const episode::EpisodeResult& r,
                        double optimal_m, std::optional<double> shortest_possible_m);

}  // namespace plantsim::batch
