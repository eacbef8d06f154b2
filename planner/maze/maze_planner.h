// Seed 003 behind the planner interface: "maze-left" and "maze-right" solve a tunnel-lattice
// world by the document's procedure (hand-rule exploration, string simplification, the ring
// search) and return the route to drive, the third string as recorded; the exploration walk,
// the ring search's walks and the letters recorded at each junction come along for figures.
// "maze-left-resimplified" and "maze-right-resimplified" drive the third string simplified
// again (plantsim's option); "maze-left-explore" and "maze-right-explore" drive the first
// inspection. On a world without a lattice they answer "no path" and say why.
#pragma once

#include "planner/maze/hand_rule.h"
#include "planner/planner.h"

namespace plantsim::planner {

class MazePlanner : public Planner {
 public:
  /// With `drive_exploration` the path is the first inspection itself: the hand-rule
  /// exploration (dead ends and all) and, when it came back to the entrance, the search walk
  /// that found the exit; otherwise the route found for the next inspections.
  MazePlanner(const PlannerInput& input, Hand hand, bool drive_exploration = false,
              ThirdString third_string = ThirdString::kAsRecorded);
  std::string name() const override {
    return std::string(hand_ == Hand::kLeft ? "maze-left" : "maze-right") +
           (drive_exploration_ ? "-explore" : "") +
           (third_string_ == ThirdString::kResimplified ? "-resimplified" : "");
  }
  PlanResult plan(Vec2 start, Vec2 goal) override;

 private:
  std::string note(const MazeSolution& s, double shortest_m) const;
  std::optional<TunnelMaze> maze_;
  Hand hand_;
  bool drive_exploration_;
  ThirdString third_string_;
};

}  // namespace plantsim::planner
