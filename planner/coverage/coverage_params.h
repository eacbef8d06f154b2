// Everything seed 004's coverage methods can be tuned by, in one place: the weights of D, the
// turn confidence's K, the networks' constants and the exact search's limits. Read from JSON by
// `plantsim coverage --params FILE` (configs/coverage_params.json holds the defaults).
#pragma once

#include "planner/coverage/exact_order.h"
#include "planner/coverage/hopfield_order.h"
#include "planner/coverage/region_order.h"
#include "planner/coverage/sweep_model.h"

namespace plantsim::planner {

struct CoverageParams {
  double cell_m = 2.0;      ///< cell size (the document: 2 x 2 m)
  CoverageWeights weights;  ///< w1, w2 of D and of the cell method's step values
  double turn_k = 1.0;      ///< K of the turn confidence (the document's experiment: 1)
  HopfieldParams chnn;
  PottsParams potts;
  ExactOrderOptions exact;
};

}  // namespace plantsim::planner
