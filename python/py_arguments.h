// Arguments run() and batch() share: a config given as a dict or a file, and Python callables
// turned into the steering of an episode.
#pragma once

#include <string>

#include "episode/episode_config.h"
#include "episode/run_episode.h"
#include "python/py_convert.h"

namespace plantsim::python {

/// None (the defaults), a dict with the keys of docs/config.md, or a config file's path.
episode::EpisodeConfig config_argument(const py::handle& config);

/// The travel and docking callables (either may be None) as an episode's steering named
/// `name`; nothing when both are None.
episode::EpisodeSteering steering_argument(const py::object& controller, const py::object& docking,
                                           const std::string& name);

/// A callable's __name__ (or its type's), for records.
std::string callable_name(const py::object& f);

}  // namespace plantsim::python
