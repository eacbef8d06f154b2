// DWB's parameters, named and defaulted as nav2_dwb_controller names them (nav2_bringup's
// FollowPath when it was DWB): the kinematics, the velocity samples, the trajectory generator
// and the critics' scales.
#pragma once

namespace plantsim::controller::dwb {

struct DwbParams {
  // Kinematics (DWBLocalPlanner's KinematicParameters)
  double min_vel_x = 0.0, max_vel_x = 0.26;    ///< m/s
  double max_vel_theta = 1.0;                  ///< rad/s
  double min_speed_theta = 0.0;                ///< rad/s: slower turns in place are not sampled
  double acc_lim_x = 2.5, decel_lim_x = -2.5;  ///< m/s^2
  double acc_lim_theta = 3.2, decel_lim_theta = -3.2;  ///< rad/s^2
  // StandardTrajectoryGenerator
  int vx_samples = 20, vtheta_samples = 20;
  double sim_time = 1.7;            ///< s each trajectory is simulated
  double time_granularity = 0.025;  ///< s between its poses (linear_granularity 0.05 at most)
  double xy_goal_tolerance = 0.25;  ///< m: within it, RotateToGoal takes over
  // Critics' scales (nav2_bringup)
  double base_obstacle_scale = 0.02;
  double path_align_scale = 32.0, goal_align_scale = 24.0;
  double path_dist_scale = 32.0, goal_dist_scale = 24.0;
  double rotate_to_goal_scale = 32.0;
  double forward_point_distance = 0.325;  ///< m ahead of the pose for the align critics
  double slowing_factor = 5.0;            ///< RotateToGoal: cost of speed near the goal
  double oscillation_reset_dist = 0.05;   ///< m driven that forgets a reversal
  double oscillation_reset_angle = 0.2;   ///< rad turned that forgets a reversal
  double x_only_threshold = 0.05;         ///< m/s: faster, turns' reversals are not tracked
  double inflation_radius_m = 0.55;       ///< the obstacle cost decays to 0 here from the footprint
  double forward_prune_distance = 2.0;    ///< m of the plan ahead the critics see
  double local_goal_margin_m = 0.05;      ///< the local goal is the furthest point of that plan
                                          ///< the footprint reaches in a straight line this clear
};

}  // namespace plantsim::controller::dwb
