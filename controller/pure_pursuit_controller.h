// Regulated pure pursuit as a registered local controller ("pure-pursuit", the default): its
// parameters keep the section they always had, "tracking", so configurations written before the
// registry read the same.
#pragma once

#include <memory>

#include "controller/local_controller.h"

namespace plantsim::controller {

struct PurePursuitParams;

/// Pure pursuit of these parameters as a local controller.
std::unique_ptr<LocalController> make_pure_pursuit(const PurePursuitParams& p);

/// Its registry entry.
LocalControllerEntry pure_pursuit_entry();

}  // namespace plantsim::controller
