// The metrics of an episode as JSON fields, written the same way into a run's summary.json
// and a batch's episode lines.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <string_view>

#include "episode/episode_result.h"

namespace plantsim::episode {

/// The fields that hold wall-clock times (the local controller's compute time per cycle): they
/// differ from run to run of the same episode, so every comparison of two runs (shards merged
/// against one run, a resumed run, a merge's duplicate check) leaves them out.
inline constexpr std::array<std::string_view, 2> kWallTimeFields = {"controller_ms_median",
                                                                    "controller_ms_p99"};

/// `j` without the wall-time fields (kWallTimeFields), for comparing two runs' records.
template <typename Json>
Json without_wall_times(Json j) {
  for (std::string_view key : kWallTimeFields) j.erase(std::string(key));
  return j;
}

/// Adds status, docked, errors, collisions, retries, stops, replans, time and lengths to j.
void add_episode_metrics(nlohmann::ordered_json& j, const EpisodeOutcome& r);

}  // namespace plantsim::episode
