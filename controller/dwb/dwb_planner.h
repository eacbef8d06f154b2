// The dynamic window approach in the manner of nav2_dwb_controller: each control cycle samples
// (v, omega) pairs in the window the accelerations reach within sim_time (as its
// StandardTrajectoryGenerator does), simulates each for sim_time (speeds ramped as the limits
// allow), scores the trajectories with DWB's critics (BaseObstacle, Oscillation, RotateToGoal,
// PathAlign, GoalAlign, PathDist, GoalDist, each times its scale) and sends the cheapest valid
// pair. Grid distances are in cells of 5 cm, as DWB's map-grid critics count them on
// nav2_bringup's local costmap; the goal critics steer to the local goal in sight
// (plan_window.h).
#pragma once

#include <vector>

#include "controller/clearance_grid.h"
#include "controller/diff_drive.h"
#include "controller/dwb/dwb_params.h"
#include "controller/dwb/oscillation.h"
#include "controller/dwb/plan_window.h"

namespace plantsim::controller::dwb {

struct DwbQuery {
  geom::Pose2 pose;
  Twist velocity;    ///< the robot's present (v, omega)
  geom::Pose2 goal;  ///< the plan's end and the heading wanted there
  const ClearanceGrid* clearance = nullptr;
  double robot_radius_m = 0.2;
};

/// One scored trajectory: its command, poses and each critic's (scaled) share.
struct ScoredTrajectory {
  Twist command;
  std::vector<geom::Pose2> poses;
  double obstacle = 0, path_align = 0, goal_align = 0, path_dist = 0, goal_dist = 0, rotate = 0;
  bool valid = true;  ///< false: a collision or an oscillation
  double total() const {
    return obstacle + path_align + goal_align + path_dist + goal_dist + rotate;
  }
};

class DwbPlanner {
 public:
  explicit DwbPlanner(DwbParams params);

  /// A new plan (a polyline in the map frame), resampled every 5 cm.
  void set_path(const std::vector<geom::Vec2>& plan);

  /// One control cycle: the cheapest valid command, or a stop when none is valid.
  Twist step(const DwbQuery& q);

  /// Every trajectory of the last cycle, scored (for the replay and the tests).
  const std::vector<ScoredTrajectory>& trajectories() const { return scored_; }
  /// The one the last cycle chose; null when none was valid (it stopped).
  const ScoredTrajectory* chosen() const {
    return chosen_ < 0 ? nullptr : &scored_[static_cast<std::size_t>(chosen_)];
  }

  /// The trajectory of (v, omega) from `q`'s pose and velocity, ramped by the limits.
  std::vector<geom::Pose2> simulate(const DwbQuery& q, Twist target) const;
  /// Its scores.
  ScoredTrajectory score(const DwbQuery& q, Twist command) const;

 private:
  /// The footprint's edge to the nearest obstacle at `s` (negative: overlapping).
  static double edge_distance(const DwbQuery& q, const geom::Pose2& s);
  double path_distance_cells(geom::Vec2 p) const;
  DwbParams p_;
  PlanWindow plan_;
  std::vector<ScoredTrajectory> scored_;
  int chosen_ = -1;  ///< in scored_
  OscillationCritic oscillation_;
};

}  // namespace plantsim::controller::dwb
