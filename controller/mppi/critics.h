// MPPI's critics, each adding its cost to every sampled trajectory, in the manner of
// nav2_mppi_controller's critics of the same names: constraints, obstacles (from the robot's
// own clearance field), goal, goal angle, path align, path follow, path angle, prefer forward.
// The path is the plan resampled densely (a visibility-graph plan is its corners only).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "controller/clearance_grid.h"
#include "controller/mppi/mppi_params.h"
#include "controller/mppi/rollouts.h"
#include "geometry/vec2.h"

namespace plantsim::controller::mppi {

/// What every critic reads: the samples, where the robot is, the path and its goal.
struct CriticInput {
  const Rollouts& rollouts;
  const MppiParams& params;
  RobotState state;
  const std::vector<geom::Vec2>& path;  ///< dense, the plan ahead of the robot (prune_distance)
  const std::vector<float>& path_s;     ///< arc length of each point along the whole plan
  geom::Pose2 goal;
  const ClearanceGrid* clearance = nullptr;  ///< none: no obstacle cost
  float robot_radius_m = 0.2f;
  /// furthest_reached(*this) when already found (all_critics finds it once for two critics).
  std::size_t furthest = static_cast<std::size_t>(-1);
  /// The robot's distance to the goal (straight line), which switches critics on and off.
  float distance_to_goal() const;
};

using Costs = Eigen::ArrayXf;  ///< one per sample

void constraint_critic(const CriticInput& in, const CriticParams& c, Costs& costs);
void obstacles_critic(const CriticInput& in, const CriticParams& c, Costs& costs);
void goal_critic(const CriticInput& in, const CriticParams& c, Costs& costs);
void goal_angle_critic(const CriticInput& in, const CriticParams& c, Costs& costs);
void path_align_critic(const CriticInput& in, const CriticParams& c, Costs& costs);
void path_follow_critic(const CriticInput& in, const CriticParams& c, Costs& costs);
void path_angle_critic(const CriticInput& in, const CriticParams& c, Costs& costs);
void prefer_forward_critic(const CriticInput& in, const CriticParams& c, Costs& costs);

/// Every critic above, in that order.
void all_critics(const CriticInput& in, const CriticParams& c, Costs& costs);

/// The index of the path point furthest along that some sample's end comes nearest to (Nav2's
/// "furthest reached" point, from which path follow and path angle look ahead).
std::size_t furthest_reached(const CriticInput& in);

}  // namespace plantsim::controller::mppi
