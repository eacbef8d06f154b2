// The plan as DWB's critics see it each cycle: the whole plan resampled every 5 cm, pruned to
// forward_prune_distance ahead of the robot's nearest point (never back), and the local goal on
// it. Nav2 takes the pruned plan's last point for the goal; a visibility-graph plan turns its
// corners at the inflated margin exactly, and a goal beyond such a corner pulls every sampled
// arc across it, into the corner's obstacle. So the local goal is the furthest point of the
// pruned plan the robot sees with its footprint clear: before a corner, the corner itself.
#pragma once

#include <cstddef>
#include <vector>

#include "controller/clearance_grid.h"
#include "geometry/vec2.h"

namespace plantsim::controller::dwb {

class PlanWindow {
 public:
  static constexpr double kSpacing_m = 0.05;  ///< the plan's resolution (a local costmap cell)

  /// A new plan (a polyline in the map frame), from its start.
  void set_path(const std::vector<geom::Vec2>& plan);

  /// This cycle's window and local goal for the robot at `robot`. With a field, the goal is the
  /// furthest point the straight line from the robot reaches keeping the footprint
  /// `sight_margin_m` clear of obstacles (or as clear as the plan and the robot are, if less).
  void update(geom::Vec2 robot, double forward_prune_distance, const ClearanceGrid* field,
              double robot_radius_m, double sight_margin_m);

  const std::vector<geom::Vec2>& window() const { return window_; }
  geom::Vec2 local_goal() const { return goal_; }
  /// The local goal stops short of the window's end: a corner hides the plan beyond it.
  bool goal_at_corner() const { return at_corner_; }

 private:
  std::vector<geom::Vec2> path_;    ///< the whole plan, every kSpacing_m
  std::size_t progress_ = 0;        ///< its point nearest the robot, never back
  std::vector<geom::Vec2> window_;  ///< forward_prune_distance of it from there
  geom::Vec2 goal_;
  bool at_corner_ = false;
};

}  // namespace plantsim::controller::dwb
