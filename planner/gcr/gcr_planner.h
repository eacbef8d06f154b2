// Seed 002 (coal-mine search-and-rescue robot): the gradient - coordinate-rotation method.
// The robot steps along the straight line to the goal (the negative gradient of distance);
// when the next step would hit an obstacle it switches to coordinate rotation, stepping along
// an axis chosen by the document's priorities (towards the goal along the axis on which the
// goal is farther, then towards it along the other axis, then away along the other, then away
// along the first), and returns to the gradient as soon as a gradient step is free. The raw
// path is then optimised locally: from where gradient motion began to where each coordinate
// rotation ended, a straight shortcut if free, else the same method planned again for that
// piece, repeated until no segment crosses an obstacle; the result is never longer than the
// raw path. A walk that gets trapped or runs past its step budget reports "no path" and why.
#pragma once

#include "planner/obstacle_map.h"
#include "planner/planner.h"

namespace plantsim::planner {

class GcrPlanner : public Planner {
 public:
  explicit GcrPlanner(const PlannerInput& input);
  std::string name() const override { return "gcr"; }
  PlanResult plan(Vec2 start, Vec2 goal) override;

  struct Walk {
    bool reached = false;
    std::string failure;            ///< why not, when not reached
    std::vector<Vec2> points;       ///< every step
    std::vector<std::size_t> rotation_ends;  ///< indices in points where a rotation run ended
    int rotations = 0;              ///< times the gradient was blocked (local obstacles met)
  };
  /// The raw gradient / coordinate-rotation walk.
  Walk walk(Vec2 start, Vec2 goal) const;

 private:
  std::vector<Vec2> optimise(const Walk& raw, int depth) const;
  ObstacleMap map_;
  double step_m_;
};

}  // namespace plantsim::planner
