// The best order of seed 004's sub-regions, proven: depth-first branch and bound over orders,
// each prefix carrying the best cost for every way its last region can be swept (so the sweep
// choices are exact too). Bounds: the cheapest ways into and out of the regions left; a split
// bound (half of each way charged to either end, Lagrangian multipliers tuned at the root); and
// the linear relaxation with subtour cuts (order_lp.h), solved at the root and again for every
// prefix of one or two regions, whose reduced costs bound the prefixes below them. A table of
// (regions done, last region) states drops any prefix another one already beats for every sweep
// of the last region (dynamic programming's pruning without its 2^n table). The first order is
// the best given one improved by moving and reversing stretches, then perturbed (double bridge)
// and improved again, 100 times with a fixed seed (fewer above about 31 regions: a work budget).
#pragma once

#include <cstdint>
#include <vector>

#include "planner/coverage/sweep_model.h"

namespace plantsim::planner {

struct ExactOrderOptions {
  /// The search stops after this many prefixes (about 5 s on the machine of docs/seeds.md's
  /// numbers), so that what it finds does not depend on the machine's load, or at the time
  /// limit, whichever comes first.
  std::uint64_t max_prefixes = 1'500'000;
  double time_limit_s = 10.0;
  std::size_t max_table_states = 1'000'000;  ///< memory: about 150 bytes each
};

struct ExactOrder {
  std::vector<int> order;
  double cost = 0;
  bool searched = false;       ///< false above 63 regions: the order is the best starting one
  bool proven = false;         ///< the search finished: no order is cheaper
  double lower_bound = 0;      ///< when not proven: no order is cheaper than this
  double seconds = 0;          ///< the first order's local search included
  std::uint64_t prefixes = 0;  ///< prefixes expanded
};

/// Beyond 63 regions nothing is searched (the state key is a 64-bit set): the order is then the
/// best starting one and `proven` is false.
ExactOrder exact_order(const SweepModel& model,
                       const std::vector<std::vector<int>>& starting_orders,
                       const ExactOrderOptions& options = {});

}  // namespace plantsim::planner
