// The metrics of an episode as JSON fields, written the same way into a run's summary.json
// and a batch's episode lines.
#pragma once

#include <nlohmann/json.hpp>

#include "episode/episode_result.h"

namespace plantsim::episode {

/// Adds status, docked, errors, collisions, retries, stops, replans, time and lengths to j.
void add_episode_metrics(nlohmann::ordered_json& j, const EpisodeOutcome& r);

}  // namespace plantsim::episode
