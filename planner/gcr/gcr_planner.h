// Seed 002 (coal-mine search-and-rescue robot): the gradient - coordinate-rotation method, as
// the document gives it. The robot steps along the straight line to the goal (the negative
// gradient of distance) by the document's step rule: one unit along the axis on which the goal
// is nearer and |dx/dy| units along the other (a last step that would pass the goal ends on it).
// When the next step would hit an obstacle it switches to coordinate rotation, one unit at a time
// along an axis chosen by the document's priorities, fixed where it met the obstacle (towards the
// goal along the axis on which the goal is farther, then towards it along the other, then away
// along the other, then away along the first); it keeps that axis while it is free and, where
// it is not, takes the next free one that does not turn straight back (the document is silent
// there); it returns to the gradient as soon as a gradient step is free. The raw walk is then
// optimised locally: from where gradient motion began to where each coordinate rotation ended, a
// straight shortcut if free, else the same method planned again for that piece, until no
// segment crosses an obstacle. "gcr-shortcut" adds plantsim's own last pass, not in the
// document: any vertex whose neighbours see each other is dropped. A walk that comes back to a
// state it was in exactly (a rotation run from the same contact point to the bit, the same steps
// from it, axis and priorities: it would loop for ever) or runs
// past its step budget (20 times the straight distance, plus 20,000 steps) reports "no path"
// and why.
#pragma once

#include "planner/obstacle_map.h"
#include "planner/planner.h"

namespace plantsim::planner {

/// The gcr family's options: `step_m`, the walk's unit step (0.1 m).
std::vector<OptionSpec> gcr_planner_options();

class GcrPlanner : public Planner {
 public:
  /// `shortcut_pass`: plantsim's variant ("gcr-shortcut"): an extra shortcut pass after the
  /// document's optimisation, and the raw walk kept when the optimisation came out longer.
  explicit GcrPlanner(const PlannerInput& input, bool shortcut_pass = false);
  std::string name() const override { return shortcut_pass_ ? "gcr-shortcut" : "gcr"; }
  PlanResult plan(Vec2 start, Vec2 goal) override;

  /// The document's gradient step from p towards goal: `unit` along the axis on which the goal
  /// is nearer, proportionally more along the other; the whole way when that is shorter.
  static Vec2 gradient_step(Vec2 p, Vec2 goal, double unit);
  /// How deep the optimisation recurses into the walks between a rotation's ends.
  static constexpr int kOptimisationDepth = 3;

  struct Walk {
    bool reached = false;
    std::string failure;                     ///< why not, when not reached
    std::vector<Vec2> points;                ///< every step
    std::vector<std::size_t> rotation_ends;  ///< indices in points where a rotation run ended
    int rotations = 0;  ///< times the gradient was blocked (local obstacles met)
    std::vector<Vec2> first_rotation_axes;  ///< the axis each rotation run set off along
  };
  /// The raw gradient / coordinate-rotation walk.
  Walk walk(Vec2 start, Vec2 goal) const;

 private:
  std::vector<Vec2> optimise(const Walk& raw, int depth) const;
  ObstacleMap map_;
  double step_m_;
  bool shortcut_pass_;
};

}  // namespace plantsim::planner
