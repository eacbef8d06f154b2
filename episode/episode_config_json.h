// EpisodeConfig from JSON: every controller, drive, sensing and docking parameter can be set
// in a config file (documented with defaults in docs/config.md). Unknown keys are errors, so
// a typo never silently leaves a default in place.
#pragma once

#include <string>

#include "sim/episode.h"

namespace plantsim::episode {

using sim::EpisodeConfig;

/// Applies the file's values over `base`. Throws worlds::WorldError naming file and field.
EpisodeConfig load_episode_config(const std::string& path, EpisodeConfig base = {});
EpisodeConfig parse_episode_config(const std::string& text, const std::string& source,
                                   EpisodeConfig base = {});

/// The defaults as JSON (what `plantsim config` prints).
std::string default_config_json();
/// `config` as JSON, every key (read back by parse_episode_config as the same config).
std::string config_json(const EpisodeConfig& config);

}  // namespace plantsim::episode
