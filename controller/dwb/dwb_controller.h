// DWB as a registered local controller ("dwb"): the planner (dwb_planner.h) fed the estimate, the
// plan and the local distance field each step; its parameters in the "dwb" section, Nav2's names
// and nav2_bringup's values (docs/controllers.md).
#pragma once

#include "controller/dwb/dwb_params.h"
#include "controller/local_controller.h"
#include "util/param_table.h"

namespace plantsim::controller::dwb {

/// The planner's parameters and what the adapter adds.
struct DwbControllerParams {
  DwbParams planner;
  double goal_tolerance_m =
      0.25;  ///< at the staging pose within this (nav2_bringup's xy_goal_tolerance:
             ///< nearer, DWB only turns to the goal heading)
};

const util::ParamRows<DwbControllerParams>& dwb_param_rows();  ///< "dwb"

/// Its registry entry.
LocalControllerEntry dwb_entry();

}  // namespace plantsim::controller::dwb
