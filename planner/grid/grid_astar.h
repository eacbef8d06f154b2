// The grid baseline: 8-connected A* over cells as the MovingAI benchmarks define it (moves
// between cell centres, diagonal cost sqrt(2), no corner cutting: a diagonal move needs both
// orthogonal neighbours free), with the octile distance as heuristic. Also a Planner that
// rasterises a world's inflated obstacles into such a grid, for the document's comparison.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "planner/planner.h"

namespace plantsim::planner {

struct GridSearchResult {
  bool found = false;
  double length = 0;
  std::vector<std::pair<int, int>> cells;  ///< (x, y) from start to goal
  std::int64_t expanded = 0;
};

/// `free(x, y)` tells whether a cell may be entered; cells outside width x height never may.
GridSearchResult grid_astar(int width, int height, const std::function<bool(int, int)>& free,
                            int sx, int sy, int gx, int gy);

/// The grid family's options: `resolution_m`, the cells' size (0.1 m).
std::vector<OptionSpec> grid_planner_options();

/// Planner "grid": cells of option `resolution_m`; a cell is blocked when it overlaps an
/// inflated obstacle's interior or lies outside the free floor; the path runs from the start
/// through cell centres to the goal.
class GridPlanner : public Planner {
 public:
  explicit GridPlanner(const PlannerInput& input);
  std::string name() const override { return "grid"; }
  PlanResult plan(Vec2 start, Vec2 goal) override;

 private:
  std::pair<int, int> cell_of(Vec2 p) const;
  Rect free_floor_;
  Vec2 origin_;
  double resolution_;
  int width_ = 0, height_ = 0;
  std::vector<char> blocked_;
  double build_ms_ = 0;
};

}  // namespace plantsim::planner
