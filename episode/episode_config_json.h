// EpisodeConfig from JSON: every controller, drive, sensing and docking parameter can be set
// in a config file (documented with defaults in docs/config.md). Unknown keys are errors, so
// a typo never silently leaves a default in place.
#pragma once

#include <string>
#include <vector>

#include "episode/episode_config.h"
#include "util/param_spec.h"

namespace plantsim::episode {

/// Applies the file's values over `base`. Throws worlds::WorldError naming file and field.
EpisodeConfig load_episode_config(const std::string& path, EpisodeConfig base);
EpisodeConfig parse_episode_config(const std::string& text, const std::string& source,
                                   EpisodeConfig base);
/// ... over the defaults (an overload, not a default argument: GCC 12 reads the temporary's
/// maps as uninitialised at every call site).
EpisodeConfig load_episode_config(const std::string& path);
EpisodeConfig parse_episode_config(const std::string& text, const std::string& source);

/// A number parameter of the configuration (not a flag or a mode), as `plantsim tune` searches it:
/// its "section.key", its documented range and its default.
struct NumberParameter {
  std::string path;
  double lo = 0, hi = 0;
  bool above = false;  ///< lo itself excluded
  bool whole = false;  ///< a whole number
  double default_value = 0;
};
/// Every number parameter, in docs/config.md's order.
std::vector<NumberParameter> number_parameters();
/// The parameter `path` ("tracking.max_linear_speed_mps"); throws std::invalid_argument naming it
/// (with the nearest known key) when the configuration has no such number.
NumberParameter number_parameter(const std::string& path);

/// The defaults as JSON (what `plantsim config` prints).
/// The values of a component's declared parameters in `config` (each from its row: a typed one,
/// or component_params, or its default), for its factory.
util::ParamValues component_values(const EpisodeConfig& config,
                                   const std::vector<util::ParamSpec>& specs);

/// The value of the number parameter `path` in `config` (throws std::invalid_argument for an
/// unknown one).
double number_value(const EpisodeConfig& config, const std::string& path);

std::string default_config_json();
/// `config` as JSON, every key (read back by parse_episode_config as the same config).
std::string config_json(const EpisodeConfig& config);

}  // namespace plantsim::episode
