// Two more ways to order seed 004's sub-regions, beside the document's network
// (hopfield_order.h) and the proven optimum (exact_order.h): annealed Potts neurons, plantsim's
// own variant of the network that settles far more often, and the nearest sweep next (greedy).
#pragma once

#include <cstdint>
#include <vector>

#include "planner/coverage/sweep_model.h"

namespace plantsim::planner {

/// Nearest next: from where the last sweep ended, the region and sweep that D says is cheapest.
std::vector<int> greedy_order(const SweepModel& model);

/// Not the document's network: neurons V[x][k] with Potts (softmax) outputs per position, so
/// that each position holds one region by construction; the energy keeps the document's
/// distance term (weight d) and the penalty for a region held at more than one position
/// (weight a); mean-field updates while the temperature is lowered (annealing). Outputs that do
/// not settle on a permutation are read position by position (the most active unused region),
/// so there is always an order; how many settled by themselves is counted.
struct PottsParams {
  double a = 1.0;         ///< penalty: a region at two positions
  double d = 1.0;         ///< weight of the (normalised) distances
  double t0 = 2.0;        ///< starting temperature
  double cooling = 0.93;  ///< temperature factor per step
  double t_min = 0.005;
  int sweeps = 4;     ///< updates of every position per temperature
  int restarts = 20;  ///< fewer on large maps: the work is capped near 3e9 updates
  std::uint64_t seed = 1;
};

struct PottsResult {
  std::vector<int> order;
  int settled_valid = 0;
  int restarts = 0;
};

PottsResult potts_order(const RegionDistances& d, const PottsParams& params = {});

}  // namespace plantsim::planner
