// The robot side's parameters as configuration rows (section, key, bounds; util/param_table.h):
// the estimators, the tracker, the local layer, perception's own thresholds and the lost search.
// Defaults live in each struct; the episode's configuration takes these rows over as they are.
#pragma once

#include "robot/coastal_route.h"
#include "robot/ekf_localizer.h"
#include "robot/global_match.h"
#include "robot/local_obstacle_layer.h"
#include "robot/lost_search.h"
#include "robot/obstacle_tracker.h"
#include "robot/particle_localizer.h"
#include "robot/perception.h"
#include "util/choice_table.h"
#include "util/param_table.h"

namespace plantsim::robot {

const util::ParamRows<EkfParams>& ekf_param_rows();                 ///< "ekf"
const util::ParamRows<TrackerParams>& tracker_param_rows();         ///< "tracker"
const util::ParamRows<ObstacleLayerParams>& layer_param_rows();     ///< "layer"
const util::ParamRows<ParticleParams>& particle_param_rows();       ///< "particles"
const util::ParamRows<LostSearchParams>& lost_search_param_rows();  ///< "lost_search"
const util::ParamRows<CoastalParams>& coastal_param_rows();         ///< "coastal"
/// "perception": perception's own thresholds and its global match's (not its parts with
/// sections of their own, above).
const util::ParamRows<PerceptionParams>& perception_param_rows();
/// perception.mode (localization.estimator is a name: estimator_registry.h).
const util::ChoiceRows<PerceptionParams>& perception_choice_rows();

}  // namespace plantsim::robot
