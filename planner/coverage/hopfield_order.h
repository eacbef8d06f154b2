// Seed 004's continuous Hopfield network (CHNN) for the order of sub-regions, as its document
// describes it: neurons V[x][k] (region x at position k), an energy of three penalty terms (a
// region at two positions: alpha; two regions at one position: beta; total activity other than
// the number of regions: gamma) plus the distance term (eta) between neighbours in the order,
// and the state equation dU/dt = -U/tau - dE/dV with V = f(U). The document's formulas (5)-(7)
// are missing from its text; the terms it names are those of Hopfield and Tank's travelling
// salesman network (1985), so that is the energy used, with their constants (alpha = beta =
// 500, gamma = 200, u0 = 0.02, dt = 1e-5) and f(U) = (1 + tanh(U / u0)) / 2; eta and the
// activity target were lowered until the network settled on the 21-region pit at all. The path is
// open: the start and the end cells are fixed neighbours of the first and last positions. A restart
// whose outputs do not settle on a permutation matrix gives no order; the share that does is
// reported, never repaired.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "planner/coverage/sweep_model.h"

namespace plantsim::planner {

struct HopfieldParams {
  double alpha = 500;          ///< a region at two positions
  double beta = 500;           ///< two regions at one position
  double gamma = 200;          ///< total activity other than its target
  double target_ratio = 1.05;  ///< the target as a multiple of the number of regions (Hopfield and
                               ///< Tank aimed at 15 for 10 cities; exactly n settled in 0 of 20
                               ///< restarts on the 21-region pit with their eta = 500)
  double eta = 100;  ///< distance between neighbours in the order (distances scaled to <= 1)
  double u0 = 0.02;  ///< gain of f
  double tau = 1.0;  ///< decay of the inputs
  double dt = 1e-5;  ///< Euler step of the state equation
  int max_steps = 20000;
  double settle_change = 1e-4;  ///< settled when no output moves more than this in a step
  int restarts = 50;
  double init_noise = 0.1;  ///< of u0: the random part of the starting inputs
  std::uint64_t seed = 1;
};

struct HopfieldResult {
  std::optional<std::vector<int>> order;  ///< the cheapest valid one over the restarts
  int valid = 0;  ///< restarts whose outputs settled on a permutation matrix
  int restarts = 0;
  int settled = 0;  ///< restarts that stopped moving within max_steps (valid or not)
};

HopfieldResult hopfield_order(const RegionDistances& d, const HopfieldParams& params = {});

}  // namespace plantsim::planner
