// Dead reckoning: the pose integrated from the encoders and the gyro alone, the lidar unused; its
// uncertainty grows with the distance driven and the time turned. The baseline every localiser
// must beat. Registered as the estimator "dead-reckoning".
#pragma once

#include "robot/estimator_registry.h"

namespace example {

plantsim::robot::EstimatorEntry dead_reckoning_entry();

}  // namespace example
