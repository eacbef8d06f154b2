// The controllers' parameters as configuration rows (section, key, bounds; util/param_table.h):
// pure pursuit, docking, traction control and seed 001's potential field. Defaults live in each
// struct; the episode's configuration takes these rows over as they are.
#pragma once

#include "controller/docking.h"
#include "controller/potential_field.h"
#include "controller/pure_pursuit.h"
#include "controller/traction.h"
#include "util/param_table.h"

namespace plantsim::controller {

const util::ParamRows<PurePursuitParams>& pure_pursuit_param_rows();        ///< "tracking"
const util::ParamRows<DockingParams>& docking_param_rows();                 ///< "docking"
const util::ParamRows<TractionParams>& traction_param_rows();               ///< "traction"
const util::ParamRows<PotentialFieldParams>& potential_field_param_rows();  ///< "potential_field"

}  // namespace plantsim::controller
