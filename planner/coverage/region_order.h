// The order in which seed 004 visits its sub-regions: an open path from the start's region
// through every region once, on the document's distance D_ij = w1 S_ij + w2 beta_ij (S: cells
// travelled between the regions, beta: turns on the way; w1 = 0.8, w2 = 0.2). Three solvers:
// the document's continuous Hopfield network (CHNN: its energy for a path, mean-field
// annealing, restarts), the exact optimum by Held-Karp dynamic programming (small counts),
// and nearest-neighbour greedy.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "planner/coverage/coverage_grid.h"

namespace plantsim::planner {

using DistanceMatrix = std::vector<std::vector<double>>;

DistanceMatrix region_distances(const CoverageGrid& grid, const std::vector<CellRect>& regions, double w_cells = 0.8,
                                double w_turns = 0.2);

/// Sum of D along the order.
double order_cost(const DistanceMatrix& d, const std::vector<int>& order);

/// Exact best open path starting at `start`; nullopt above `max_regions` (2^n n^2 work).
std::optional<std::vector<int>> held_karp_order(const DistanceMatrix& d, int start, int max_regions = 20);

std::vector<int> greedy_order(const DistanceMatrix& d, int start);

/// The network: neurons V[x][k] (region x at position k) with Potts (softmax) outputs per
/// position, so that each position holds one region; the energy is the document's, distance
/// between neighbours in the order (weight d) plus a penalty for a region held at more than one
/// position (weight a); mean-field updates while the temperature is lowered (annealing) until
/// the outputs saturate. (The plain Hopfield-Tank dynamics with all constraints as penalties
/// settled on a permutation in 0 of 10 restarts on our 10-20 region maps; these outputs
/// mostly do, and the read-out repairs the rest.)
struct ChnnParams {
  double a = 1.0;        ///< penalty: a region at two positions
  double d = 1.0;        ///< weight of the (normalised) distances
  double t0 = 2.0;       ///< starting temperature
  double cooling = 0.93; ///< temperature factor per step
  double t_min = 0.005;
  int sweeps = 4;        ///< updates of every position per temperature
  int restarts = 20;
  std::uint64_t seed = 1;
};

struct ChnnResult {
  std::vector<int> order;   ///< always a permutation starting at `start`
  int settled_valid = 0;    ///< restarts whose outputs settled on a permutation matrix by themselves
  int restarts = 0;
};

/// The network's best order over its restarts; outputs that did not settle on a permutation
/// are read position by position (the most active unused region), so the order is valid.
ChnnResult chnn_order(const DistanceMatrix& d, int start, const ChnnParams& params = {});

}  // namespace plantsim::planner
