// Whether a tuning's validation episodes are really held out: an episode is its world's
// content and its seed (the start, the noise and the faults follow from them), so a world is
// judged by its content fingerprint, never by the path that named it (`./w.json`,
// `sub/../w.json`, a link or a copy of a tuning world are that world).
#pragma once

#include "batch/batch_spec.h"
#include "batch/scenario_setup.h"

namespace plantsim::tune {

/// Throws worlds::WorldError naming the scenario's field when a validation world has the content
/// of a tuning world and the two parts share a seed.
void check_held_out(const batch::BatchSpec& tuning, const batch::ScenarioWorlds& tuning_worlds,
                    const batch::BatchSpec& validation,
                    const batch::ScenarioWorlds& validation_worlds);

}  // namespace plantsim::tune
