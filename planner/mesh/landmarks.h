// Landmarks for the mesh searches' ALT heuristic (Goldberg and Harrelson 2005): which points to
// measure from, the table of exact distances from each, and the lower bound the table gives.
// The rectangle mesh's search and the convex mesh's share it; each brings its own points and
// its own way of measuring every distance from one of them (a search with no goal).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace plantsim::planner {

struct LandmarkTable {
  int landmarks = 0;
  std::vector<double> distance;  ///< per point, `landmarks` wide; NaN: not known
};

/// Up to `count` landmarks among `points` points: point `first`, then each the point farthest
/// from all before it, until `count` or every point is a landmark's. `distances_from(i)`: the
/// exact distance from point i to every point (infinity: unreachable). A point `unusable(i)`
/// (a pinch, whose distance depends on the side it is reached from) keeps NaN.
LandmarkTable measure_landmarks(
    int count, std::size_t points, std::size_t first,
    const std::function<std::vector<double>(std::size_t)>& distances_from,
    const std::function<bool(std::size_t)>& unusable);

/// The landmarks' lower bound on the distance between a point whose distance from landmark k
/// lies in [low[k], high[k]] and the goal, whose lies in [goal_low[k], goal_high[k]]: the most
/// of goal_low - high and low - goal_high over the landmarks (NaN bounds give nothing), a hair
/// less, so that rounding never makes it overestimate.
/// Inline: the searches call it for every node they queue.
inline double landmark_bound(const double* low, const double* high,
                             const std::vector<double>& goal_low,
                             const std::vector<double>& goal_high, double tolerance) {
  double h = 0;
  // Unknown distances are NaN: `a > h` is false for them, so they leave h alone.
  for (std::size_t k = 0; k < goal_low.size(); ++k) {
    const double a = goal_low[k] - high[k], b = low[k] - goal_high[k];
    h = a > h ? a : h;
    h = b > h ? b : h;
  }
  return h > 0 ? h * (1 - 1e-12) - tolerance : 0;
}

}  // namespace plantsim::planner
