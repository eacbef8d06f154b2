// A Stanley path follower (Thrun et al., "Stanley: the robot that won the DARPA Grand
// Challenge", 2006), for a differential drive: the heading error to the nearest leg plus the
// arctangent of the cross-track error over the speed, turned into a yaw rate; in place at sharp
// corners. Registered as the local controller "stanley".
#pragma once

#include "controller/local_controller.h"

namespace example {

plantsim::controller::LocalControllerEntry stanley_entry();

}  // namespace example
