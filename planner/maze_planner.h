// Seed 003 behind the planner interface: "maze-left" and "maze-right" solve a tunnel-lattice
// world by the document's procedure (hand-rule exploration, string simplification, the ring
// search) and return the route to drive; the exploration walk comes along for figures. On a
// world without a lattice they answer "no path" and say why.
#pragma once

#include "planner/hand_rule.h"
#include "planner/planner.h"

namespace plantsim::planner {

class MazePlanner : public Planner {
 public:
  MazePlanner(const PlannerInput& input, Hand hand);
  std::string name() const override { return hand_ == Hand::kLeft ? "maze-left" : "maze-right"; }
  PlanResult plan(Vec2 start, Vec2 goal) override;

 private:
  std::optional<TunnelMaze> maze_;
  Hand hand_;
};

}  // namespace plantsim::planner
