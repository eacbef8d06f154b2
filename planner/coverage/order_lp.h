// A lower bound of seed 004's order problem from its linear relaxation, for the exact search.
// The order is a path from the start through one sweep of every region to the end: a
// generalised travelling salesman path. Its relaxation: a share x of every way between sweeps,
// one unit into every region, as much out of every sweep as into it, and at least one unit out
// of every set of regions (subtour cuts, added while a maximum flow finds one violated). GLPK
// solves it. Its duals y (equalities) and z >= 0 (cuts) give, for every way a, the reduced cost
// rc_a = c_a - y.A_a - z.G_a, and for every order T: cost(T) >= base + sum over T's ways of rc_a,
// whatever y and z are (base = y.b + sum z). So a prefix's reduced costs bound its completions.
// The search solves it again for orders that start with a given prefix (ways that leave the
// prefix elsewhere closed), which is tighter in that subtree.
#pragma once

#include <chrono>
#include <cstddef>
#include <memory>
#include <vector>

#include "planner/coverage/sweep_model.h"

namespace plantsim::planner {

class OrderRelaxation {
 public:
  struct Bound {
    bool solved = false;  ///< false: GLPK stopped at the deadline or failed; nothing else is set
    double value = 0;     ///< the relaxation's optimum: no order (with the prefix) is cheaper
    double base = 0;      ///< y.b + sum z, less a rounding margin
    std::vector<double> reduced;  ///< per way, indexed by way() / way_to_end()
  };

  explicit OrderRelaxation(const SweepModel& model);
  ~OrderRelaxation();
  OrderRelaxation(const OrderRelaxation&) = delete;
  OrderRelaxation& operator=(const OrderRelaxation&) = delete;

  /// The relaxation of the orders that start with `prefix` (regions), solved by the deadline.
  Bound solve(const std::vector<int>& prefix, std::chrono::steady_clock::time_point deadline);

  /// Index of the way from region i's sweep v (kStart: the start) to region j's sweep w.
  std::size_t way(int i, int v, int j, int w) const { return node(i, v) * nodes_ + node(j, w); }
  std::size_t way_to_end(int i, int v) const { return node(i, v) * nodes_ + nodes_ - 1; }
  int cuts() const;

 private:
  std::size_t node(int i, int v) const { return i == SweepModel::kStart ? 0 : offset_[i] + v; }
  void close_all_but(const std::vector<int>& prefix);
  void reduce(Bound& bound, std::size_t cuts_in_solution) const;

  struct Lp;
  std::vector<std::size_t> offset_;
  std::size_t nodes_ = 0;  // the start, every sweep, the end
  std::unique_ptr<Lp> lp_;
};

}  // namespace plantsim::planner
