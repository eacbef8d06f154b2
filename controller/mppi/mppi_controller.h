// MPPI as a registered local controller ("mppi"): the optimiser (mppi_optimizer.h) fed the
// estimate, the plan and the local distance field each step; its parameters in the "mppi"
// section, Nav2's names and defaults (docs/controllers.md).
#pragma once

#include "controller/local_controller.h"
#include "controller/mppi/mppi_params.h"
#include "util/param_table.h"

namespace plantsim::controller::mppi {

/// The optimiser's and critics' parameters and what the adapter adds.
struct MppiControllerParams {
  MppiParams optimizer;
  CriticParams critics;
  double goal_tolerance_m = 0.1;  ///< at the staging pose within this (Nav2's goal checker: 0.25)
};

const util::ParamRows<MppiControllerParams>& mppi_param_rows();  ///< "mppi"

/// Its registry entry.
LocalControllerEntry mppi_entry();

}  // namespace plantsim::controller::mppi
