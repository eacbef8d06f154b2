// MPPI's parameters, named and defaulted as nav2_mppi_controller names them (its configuration
// guide and nav2_bringup's nav2_params.yaml), so that an imported Nav2 file means the same here.
#pragma once

namespace plantsim::controller::mppi {

struct MppiParams {
  int batch_size = 2000;                ///< sampled control sequences per iteration
  int time_steps = 56;                  ///< steps of each sequence
  double model_dt = 0.05;               ///< s per step (Nav2 sets it to the control period)
  int iteration_count = 1;              ///< optimisations per control cycle
  double temperature = 0.3;             ///< softmax temperature over the trajectories' costs
  double gamma = 0.015;                 ///< weight of the control cost against the noise (Williams)
  double vx_std = 0.2;                  ///< m/s, the forward speed's sampling noise
  double wz_std = 0.4;                  ///< rad/s, the yaw rate's sampling noise
  double vx_max = 0.5, vx_min = -0.35;  ///< m/s
  double wz_max = 1.9;                  ///< rad/s
  double ax_max = 3.0, ax_min = -3.0;   ///< m/s^2 (ax_min negative: braking)
  double az_max = 3.5;                  ///< rad/s^2
  double prune_distance = 1.7;          ///< m of the plan ahead of the robot the critics see
};

/// The critics' weights and thresholds (nav2_bringup's values).
struct CriticParams {
  // ConstraintCritic
  double constraint_weight = 4.0;
  // ObstaclesCritic: distances from the footprint's edge (m)
  double critical_weight = 20.0;
  double repulsion_weight = 1.5;
  double collision_cost = 10000.0;
  double collision_margin_distance = 0.1;
  double inflation_radius = 0.55;
  double obstacles_near_goal_distance = 0.5;  ///< nearer the goal, repulsion stops
  // GoalCritic, GoalAngleCritic
  double goal_weight = 5.0;
  double goal_threshold_to_consider = 1.4;
  double goal_angle_weight = 3.0;
  double goal_angle_threshold_to_consider = 0.5;
  // PathAlignCritic
  double path_align_weight = 14.0;
  int path_align_trajectory_point_step = 4;
  double path_align_threshold_to_consider = 0.5;
  double max_path_occupancy_ratio = 0.05;  ///< more of the path ahead blocked: no alignment
  // PathFollowCritic
  double path_follow_weight = 5.0;
  int path_follow_offset_from_furthest = 5;
  double path_follow_threshold_to_consider = 1.4;
  // PathAngleCritic
  double path_angle_weight = 2.0;
  int path_angle_offset_from_furthest = 4;
  double path_angle_threshold_to_consider = 0.5;
  double max_angle_to_furthest = 1.0;  ///< rad: below it, the heading is left alone
  // PreferForwardCritic
  double prefer_forward_weight = 5.0;
  double prefer_forward_threshold_to_consider = 0.5;
};

}  // namespace plantsim::controller::mppi
