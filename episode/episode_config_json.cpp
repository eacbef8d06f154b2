// A table of every parameter, read and written by the same entries.
#include "episode/episode_config_json.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "util/input_file.h"
#include "util/param_table.h"
#include "worlds/json_input.h"
#include "worlds/known_keys.h"
#include "worlds/world_error.h"

namespace plantsim::episode {

using namespace plantsim::sim;  // the simulator's parts and the episode's types

using robot::PerceptionMode;

namespace {

using nlohmann::json;

// No parameter is meaningful beyond this; a bound keeps 1e308 out of the physics (it would
// turn forces non-finite) and out of step counts (a timeout of 1e308 never ends).
constexpr double kMaxParameter = 1e6;

using Field = util::Param<EpisodeConfig>;

const std::vector<Field>& fields() {
  static const std::vector<Field> table = {
      PLANTSIM_PARAM("step", step.dt_s, "dt_s", 1e-4, 0.1),
      PLANTSIM_PARAM("drive", drive.tyre_friction, "tyre_friction", 0.0, kMaxParameter),
      PLANTSIM_PARAM("odometry", odometry.wheel_speed_noise, "wheel_speed_noise", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("odometry", odometry.left_scale_error, "left_scale_error", -0.5, 0.5),
      PLANTSIM_PARAM("odometry", odometry.right_scale_error, "right_scale_error", -0.5, 0.5),
      PLANTSIM_PARAM("localization", localization.period_s, "period_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("localization", localization.position_noise_m, "position_noise_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("localization", localization.yaw_noise_rad, "yaw_noise_rad", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("detection", detection.range_m, "range_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("detection", detection.field_of_view_rad, "field_of_view_rad", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("detection", detection.position_noise_m, "position_noise_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("detection", detection.yaw_noise_rad, "yaw_noise_rad", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("detection", detection.rate_hz, "rate_hz", 0.0, 1000.0),
      PLANTSIM_PARAM("detection", detection.mount_x_m, "mount_x_m", -10.0, 10.0),
      PLANTSIM_PARAM("detection", detection.false_negative_probability,
                     "false_negative_probability", 0.0, 1.0),
      PLANTSIM_PARAM("detection", detection.outlier_probability, "outlier_probability", 0.0, 1.0),
      PLANTSIM_PARAM("detection", detection.outlier_position_m, "outlier_position_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("detection", detection.outlier_yaw_rad, "outlier_yaw_rad", 0.0, kMaxParameter),
      PLANTSIM_PARAM("detection", detection.latency_s, "latency_s", 0.0, 1.5),
      PLANTSIM_PARAM_ABOVE("lidar", lidar.field_of_view_rad, "field_of_view_rad", 0.0, 2.0 * M_PI),
      PLANTSIM_PARAM("lidar", lidar.min_range_m, "min_range_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("lidar", lidar.max_range_m, "max_range_m", 0.0, 1000.0),
      PLANTSIM_PARAM_ABOVE("lidar", lidar.rate_hz, "rate_hz", 0.0, 1000.0),
      PLANTSIM_PARAM("lidar", lidar.mount_x_m, "mount_x_m", -10.0, 10.0),
      PLANTSIM_PARAM("lidar", lidar.mount_y_m, "mount_y_m", -10.0, 10.0),
      PLANTSIM_PARAM("lidar", lidar.mount_yaw_rad, "mount_yaw_rad", -M_PI, M_PI),
      PLANTSIM_PARAM("lidar", lidar.range_noise_m, "range_noise_m", 0.0, 10.0),
      PLANTSIM_PARAM("lidar", lidar.dropout_probability, "dropout_probability", 0.0, 1.0),
      PLANTSIM_PARAM("imu", imu.yaw_rate_noise_radps, "yaw_rate_noise_radps", 0.0, 10.0),
      PLANTSIM_PARAM("imu", imu.bias_radps, "bias_radps", 0.0, 10.0),
      PLANTSIM_PARAM("imu", imu.bias_walk_radps_per_sqrt_s, "bias_walk_radps_per_sqrt_s", 0.0,
                     10.0),
      PLANTSIM_PARAM("beacon", beacon.position_noise_m, "position_noise_m", 0.0, 100.0),
      PLANTSIM_PARAM_ABOVE("ekf", perception.ekf.initial_position_sigma_m,
                           "initial_position_sigma_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", perception.ekf.initial_yaw_sigma_rad, "initial_yaw_sigma_rad",
                           0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", perception.ekf.initial_bias_sigma_radps,
                           "initial_bias_sigma_radps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("ekf", perception.ekf.distance_noise, "distance_noise", 0.0, kMaxParameter),
      PLANTSIM_PARAM("ekf", perception.ekf.lateral_noise, "lateral_noise", 0.0, kMaxParameter),
      PLANTSIM_PARAM("ekf", perception.ekf.gyro_noise_radps, "gyro_noise_radps", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("ekf", perception.ekf.bias_walk_radps_per_sqrt_s, "bias_walk_radps_per_sqrt_s",
                     0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", perception.ekf.range_sigma_m, "range_sigma_m", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", perception.ekf.gate_chi2, "gate_chi2", 0.0, kMaxParameter),
      PLANTSIM_PARAM("ekf", perception.ekf.min_incidence_cos, "min_incidence_cos", 0.0, 1.0),
      PLANTSIM_PARAM("ekf", perception.ekf.range_learning_rate, "range_learning_rate", 0.0, 1.0),
      PLANTSIM_PARAM("ekf", perception.ekf.gyro_learning_rate, "gyro_learning_rate", 0.0, 1.0),
      PLANTSIM_PARAM("ekf", perception.ekf.gate_floor_m, "gate_floor_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", perception.ekf.constraint_sigma_m, "constraint_sigma_m", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM("ekf", perception.ekf.degraded_inlier_fraction, "degraded_inlier_fraction",
                     0.0, 1.0),
      PLANTSIM_PARAM_ABOVE("ekf", perception.ekf.ok_position_sigma_m, "ok_position_sigma_m", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", perception.ekf.nis_quantile_z, "nis_quantile_z", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", perception.ekf.lost_position_sigma_m, "lost_position_sigma_m",
                           0.0, kMaxParameter),
      PLANTSIM_PARAM("tracker", perception.tracker.unexplained_margin_m, "unexplained_margin_m",
                     0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("tracker", perception.tracker.range_m, "range_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("tracker", perception.tracker.cluster_gap_m, "cluster_gap_m", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM_ABOVE("tracker", perception.tracker.association_gate_m, "association_gate_m",
                           0.0, kMaxParameter),
      PLANTSIM_PARAM("tracker", perception.tracker.alpha, "alpha", 0.0, 1.0),
      PLANTSIM_PARAM("tracker", perception.tracker.beta, "beta", 0.0, 1.0),
      PLANTSIM_PARAM_ABOVE("tracker", perception.tracker.max_speed_mps, "max_speed_mps", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM("tracker", perception.tracker.still_speed_mps, "still_speed_mps", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM_ABOVE("tracker", perception.tracker.forget_after_s, "forget_after_s", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM("tracker", perception.tracker.min_size_m, "min_size_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracker", perception.tracker.assumed_depth_m, "assumed_depth_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("perception", perception.target_exclusion_m, "target_exclusion_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.lookahead_min_m, "lookahead_min_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.lookahead_max_m, "lookahead_max_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.lookahead_time_s, "lookahead_time_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.sharp_turn_rad, "sharp_turn_rad", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.corner_release_m, "corner_release_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.max_linear_speed_mps, "max_linear_speed_mps", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.max_angular_speed_radps, "max_angular_speed_radps", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.min_approach_speed_mps, "min_approach_speed_mps", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.approach_slowdown_distance_m,
                     "approach_slowdown_distance_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.regulated_min_radius_m, "regulated_min_radius_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.rotate_in_place_threshold_rad,
                     "rotate_in_place_threshold_rad", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.rotate_in_place_exit_rad, "rotate_in_place_exit_rad", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.rotate_in_place_speed_radps,
                     "rotate_in_place_speed_radps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.goal_tolerance_m, "goal_tolerance_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", tracking.progress_window_m, "progress_window_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("docking", docking.approach_speed_mps, "approach_speed_mps", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("docking", docking.approach_lookahead_m, "approach_lookahead_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("docking", docking.align_tolerance_rad, "align_tolerance_rad", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("docking", docking.align_speed_radps, "align_speed_radps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", docking.backoff_speed_mps, "backoff_speed_mps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", docking.overshoot_limit_m, "overshoot_limit_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", docking.detection_blend, "detection_blend", 0.0, 1.0),
      PLANTSIM_PARAM_ABOVE("docking", docking.detection_gate_m, "detection_gate_m", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM("docking", docking.approach_timeout_s, "approach_timeout_s", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("docking", docking.safety_margin_m, "safety_margin_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", docking.max_decel_mps2, "max_decel_mps2", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", docking.check_extra_m, "check_extra_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", docking.replan_after_s, "replan_after_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", docking.yield_horizon_s, "yield_horizon_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", docking.yield_speed_mps, "yield_speed_mps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", docking.bystander_reach_m, "bystander_reach_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", docking.bystander_max_size_m, "bystander_max_size_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("docking", docking.bystander_wait_s, "bystander_wait_s", 0.0, 86400.0),
      PLANTSIM_PARAM("kidnap", kidnap.at_s, "at_s", -1.0, 86400.0),
      PLANTSIM_PARAM("kidnap", kidnap.dx_m, "dx_m", -1000.0, 1000.0),
      PLANTSIM_PARAM("kidnap", kidnap.dy_m, "dy_m", -1000.0, 1000.0),
      PLANTSIM_PARAM("kidnap", kidnap.dyaw_rad, "dyaw_rad", -M_PI, M_PI),
      PLANTSIM_PARAM("kidnap", kidnap.distance_min_m, "distance_min_m", 0.0, 1000.0),
      PLANTSIM_PARAM("kidnap", kidnap.distance_max_m, "distance_max_m", 0.0, 1000.0),
      PLANTSIM_PARAM("docking", docking.confident_sigma_m, "confident_sigma_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", docking.uncertain_sigma_m, "uncertain_sigma_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", docking.uncertain_speed_fraction, "uncertain_speed_fraction", 0.0,
                     1.0),
      PLANTSIM_PARAM("potential_field", field.k_att, "k_att", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.m, "m", 0.0, 10.0),  // exponents
      PLANTSIM_PARAM("potential_field", field.k_att_v, "k_att_v", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.m_v, "m_v", 0.0, 10.0),  // exponents
      PLANTSIM_PARAM("potential_field", field.k_rep, "k_rep", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.n, "n", 0.0, 10.0),  // exponents
      PLANTSIM_PARAM("potential_field", field.rho0_m, "rho0_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.k_rep_v, "k_rep_v", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.n_v, "n_v", 0.0, 10.0),  // exponents
      PLANTSIM_PARAM("potential_field", field.rho_min_m, "rho_min_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.max_speed_mps, "max_speed_mps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.turn_gain, "turn_gain", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.max_angular_speed_radps, "max_angular_speed_radps",
                     0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.max_decel_mps2, "max_decel_mps2", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.arrive_radius_m, "arrive_radius_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.slow_force_ratio, "slow_force_ratio", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.balance_ratio, "balance_ratio", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.stall_window_s, "stall_window_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.stall_distance_m, "stall_distance_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.wall_distance_m, "wall_distance_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.wall_gain, "wall_gain", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.follow_angle_rad, "follow_angle_rad", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.leave_margin_m, "leave_margin_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", field.sensor_range_m, "sensor_range_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("pursuit", catch_distance_m, "catch_distance_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("pursuit", pursuit_replan_period_s, "replan_period_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("perception", perception.range_m, "range_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tolerance", tolerance.position_m, "position_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tolerance", tolerance.heading_rad, "heading_rad", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tolerance", tolerance.dwell_s, "dwell_s", 0.0, 60.0),
      PLANTSIM_PARAM("tolerance", tolerance.min_press_m, "min_press_m", 0.0, 0.05),
      PLANTSIM_PARAM_ABOVE("docking", docking.press_speed_mps, "press_speed_mps", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM_ABOVE("docking", docking.press_timeout_s, "press_timeout_s", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM_ABOVE("docking", docking.stuck_timeout_s, "stuck_timeout_s", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM("docking", docking.settle_s, "settle_s", 0.0, 60.0),
      PLANTSIM_PARAM_ABOVE("traction", traction.max_accel_mps2, "max_accel_mps2", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM_ABOVE("traction", traction.max_angular_accel_radps2,
                           "max_angular_accel_radps2", 0.0, kMaxParameter),
      PLANTSIM_PARAM("traction", traction.slip_scale_factor, "slip_scale_factor", 0.0, 1.0),
      PLANTSIM_PARAM("traction", traction.min_scale, "min_scale", 0.0, 1.0),
      PLANTSIM_PARAM("traction", traction.slip_hold_s, "slip_hold_s", 0.0, 60.0),
      PLANTSIM_PARAM("traction", traction.recover_per_s, "recover_per_s", 0.0, 10.0),
      PLANTSIM_PARAM("traction", traction.creep_mps, "creep_mps", 0.0, 10.0),
      PLANTSIM_PARAM("traction", traction.creep_radps, "creep_radps", 0.0, 10.0),
      PLANTSIM_PARAM_ABOVE("layer", perception.layer.cell_m, "cell_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("layer", perception.layer.clear_range_m, "clear_range_m", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM("perception", perception.moving_speed_mps, "moving_speed_mps", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("perception", perception.explained_sigmas, "explained_sigmas", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("perception", perception.gyro_calibration_s, "gyro_calibration_s", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM_ABOVE("perception", perception.displaced_jump_m, "displaced_jump_m", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM_ABOVE("perception", perception.slip_jump_m, "slip_jump_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("perception", perception.slip_turn_radps, "slip_turn_radps", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM("perception", perception.relocalize_sigma_m, "relocalize_sigma_m", 0.0, 10.0),
      PLANTSIM_PARAM_ABOVE("perception", perception.slip_window_s, "slip_window_s", 0.0, 10.0),
      PLANTSIM_PARAM_ABOVE("perception", perception.global.global_match_sigma_m,
                           "global_match_sigma_m", 0.0, 100.0),
      PLANTSIM_PARAM("perception", perception.global.global_match_period_s, "global_match_period_s",
                     0.0, 100.0),
      PLANTSIM_PARAM("perception", perception.global.global_match_max_window_m,
                     "global_match_max_window_m", 0.1, 100.0),
      PLANTSIM_PARAM_ABOVE("particles", perception.particles.kld_error, "kld_error", 0.0, 1.0),
      PLANTSIM_PARAM_ABOVE("particles", perception.particles.kld_z, "kld_z", 0.0, 10.0),
      PLANTSIM_PARAM_ABOVE("particles", perception.particles.bin_xy_m, "bin_xy_m", 0.0, 100.0),
      PLANTSIM_PARAM_ABOVE("particles", perception.particles.bin_yaw_rad, "bin_yaw_rad", 0.0, M_PI),
      PLANTSIM_PARAM("particles", perception.particles.z_hit, "z_hit", 0.0, 1.0),
      PLANTSIM_PARAM_ABOVE("particles", perception.particles.z_rand, "z_rand", 0.0, 1.0),
      PLANTSIM_PARAM("particles", perception.particles.unsettled_sigma_m, "unsettled_sigma_m", 0.0,
                     10.0),
      PLANTSIM_PARAM("particles", perception.particles.update_min_m, "update_min_m", 0.0, 100.0),
      PLANTSIM_PARAM("particles", perception.particles.update_min_rad, "update_min_rad", 0.0, M_PI),
      PLANTSIM_PARAM("particles", perception.particles.alpha_slow, "alpha_slow", 0.0, 1.0),
      PLANTSIM_PARAM("particles", perception.particles.alpha_fast, "alpha_fast", 0.0, 1.0),
      PLANTSIM_PARAM("particles", perception.particles.jitter_m, "jitter_m", 0.0, 10.0),
      PLANTSIM_PARAM("particles", perception.particles.jitter_rad, "jitter_rad", 0.0, M_PI),
      PLANTSIM_PARAM("particles", perception.particles.contradicted_agreement,
                     "contradicted_agreement", 0.0, 1.0),
      PLANTSIM_PARAM("particles", perception.particles.reseed_fraction, "reseed_fraction", 0.0,
                     0.9),
      PLANTSIM_PARAM_ABOVE("particles", perception.particles.reseed_tile_m, "reseed_tile_m", 0.0,
                           50.0),
      PLANTSIM_PARAM("particles", perception.particles.min_explained, "min_explained", 0.0, 1.0),
      PLANTSIM_PARAM("particles", perception.particles.confirm_turn_rad, "confirm_turn_rad", 0.0,
                     100.0),
      PLANTSIM_PARAM("particles", perception.particles.confirm_move_m, "confirm_move_m", 0.0,
                     1000.0),
      PLANTSIM_PARAM("particles", perception.particles.rival_margin, "rival_margin", 0.0, 1e6),
      PLANTSIM_PARAM("particles", perception.particles.place_offset_m, "place_offset_m", 0.0,
                     100.0),
      PLANTSIM_PARAM_ABOVE("docking", docking.relocalize_timeout_s, "relocalize_timeout_s", 0.0,
                           86400.0),
      PLANTSIM_PARAM_ABOVE("lost_search", lost_search.speed_mps, "speed_mps", 0.0, 5.0),
      PLANTSIM_PARAM_ABOVE("lost_search", lost_search.turn_radps, "turn_radps", 0.0, 10.0),
      PLANTSIM_PARAM_ABOVE("lost_search", lost_search.leg_m, "leg_m", 0.0, 1000.0),
      PLANTSIM_PARAM("lost_search", lost_search.clearance_m, "clearance_m", 0.0, 10.0),
      PLANTSIM_PARAM("lost_search", lost_search.narrow_clearance_m, "narrow_clearance_m", 0.0,
                     10.0),
      PLANTSIM_PARAM("lost_search", lost_search.standoff_m, "standoff_m", 0.0, 100.0),
      PLANTSIM_PARAM_ABOVE("lost_search", lost_search.surface_reach_m, "surface_reach_m", 0.0,
                           1000.0),
      PLANTSIM_PARAM_ABOVE("", timeout_s, "timeout_s", 0.0, 86400.0),
  };
  return table;
}

// Whole-number and on/off parameters, kept apart from the real ones (and written after them).
const std::vector<Field>& int_fields() {
  static const std::vector<Field> table = {
      PLANTSIM_PARAM("step", step.velocity_iterations, "velocity_iterations", 0, 1000),
      PLANTSIM_PARAM("step", step.position_iterations, "position_iterations", 0, 1000),
      PLANTSIM_PARAM("docking", docking.max_retries, "max_retries", 0, 1000),
      PLANTSIM_PARAM("step", control_period_steps, "control_period_steps", 1, 1000),
      PLANTSIM_PARAM("potential_field", field.max_wall_follows, "max_wall_follows", 0, 1000),
      PLANTSIM_PARAM("lidar", lidar.beam_count, "beam_count", 1, 10000),
      PLANTSIM_PARAM("ekf", perception.ekf.beams_used, "beams_used", 1, 10000),
      PLANTSIM_PARAM("ekf", perception.ekf.iterations, "iterations", 1, 20),
      PLANTSIM_PARAM("ekf", perception.ekf.min_informative_beams, "min_informative_beams", 3,
                     10000),
      PLANTSIM_PARAM("ekf", perception.ekf.nis_window, "nis_window", 1, 1000),
      PLANTSIM_PARAM("ekf", perception.ekf.lost_failed_matches, "lost_failed_matches", 1, 100000),
      PLANTSIM_PARAM("ekf", perception.ekf.gyro_min_samples, "gyro_min_samples", 1, 100000),
      PLANTSIM_PARAM("particles", perception.particles.min_particles, "min_particles", 1, 100000),
      PLANTSIM_PARAM("particles", perception.particles.max_particles, "max_particles", 1, 100000),
      PLANTSIM_PARAM("particles", perception.particles.beams, "beams", 1, 10000),
      PLANTSIM_PARAM("particles", perception.particles.reseed_rings, "reseed_rings", 1, 10),
      PLANTSIM_PARAM("particles", perception.particles.min_returns, "min_returns", 1, 100000),
      PLANTSIM_PARAM("particles", perception.particles.confirm_strikes, "confirm_strikes", 1, 1000),
      PLANTSIM_PARAM("particles", perception.particles.max_places, "max_places", 1, 1000),
      PLANTSIM_PARAM("particles", perception.particles.view_change_returns, "view_change_returns",
                     1, 100000),
      PLANTSIM_PARAM("particles", perception.particles.view_change_lost_scans,
                     "view_change_lost_scans", 1, 100000),
      PLANTSIM_PARAM("particles", perception.particles.seed, "seed", 0, 1000000000),
  };
  return table;
}

const std::vector<Field>& bool_fields() {
  static const std::vector<Field> table = {
      PLANTSIM_PARAM("detection", detection.enabled, "enabled", 0, 1),
      PLANTSIM_PARAM("detection", detection.occlusion, "occlusion", 0, 1),
      PLANTSIM_PARAM("lidar", lidar.enabled, "enabled", 0, 1),
      PLANTSIM_PARAM("lidar", lidar.max_range_returns, "max_range_returns", 0, 1),
      PLANTSIM_PARAM("traction", traction.enabled, "enabled", 0, 1),
      PLANTSIM_PARAM("docking", docking.undock, "undock", 0, 1),
      PLANTSIM_PARAM("layer", perception.layer.enabled, "enabled", 0, 1),
      PLANTSIM_PARAM("ekf", perception.ekf.learn_noise, "learn_noise", 0, 1),
      PLANTSIM_PARAM("lost_search", lost_search.enabled, "enabled", 0, 1),
  };
  return table;
}

std::string path_of(const char* section, const std::string& name) {
  return std::string(section).empty() ? name : std::string(section) + "." + name;
}

}  // namespace

namespace {

/// The document's values looked up by section and name, each lookup remembered: what was never
/// looked up is an unknown parameter.
class ConfigLookup {
 public:
  ConfigLookup(const json& doc, const std::string& source) : doc_(doc), source_(source) {}
  const json* operator()(const char* section, const char* name) {
    known_.insert(path_of(section, name));
    const json* obj = &doc_;
    if (std::string(section).size()) {
      auto it = doc_.find(section);
      if (it == doc_.end()) return nullptr;
      if (!it->is_object()) throw worlds::WorldError(source_, section, "expected an object");
      obj = &*it;
    }
    auto it = obj->find(name);
    return it == obj->end() ? nullptr : &*it;
  }
  /// Refuses a key no lookup asked for.
  void refuse_unknown() const {
    for (const auto& [key, value] : doc_.items()) {
      if (value.is_object()) {
        for (const auto& [sub, _] : value.items())
          if (!known_.count(key + "." + sub))
            throw worlds::WorldError(source_, key + "." + sub, "unknown parameter");
      } else if (!known_.count(key) && key != "comment") {
        throw worlds::WorldError(source_, key, "unknown parameter");
      }
    }
  }

 private:
  const json& doc_;
  const std::string& source_;
  std::set<std::string> known_;
};

void read_tables(ConfigLookup& lookup, const std::string& source, EpisodeConfig& c) {
  for (const Field& f : fields()) {
    const json* v = lookup(f.section, f.name);
    if (!v) continue;
    if (!v->is_number())
      throw worlds::WorldError(source, path_of(f.section, f.name), "expected a number");
    const double d = v->get<double>();
    if (!std::isfinite(d))
      throw worlds::WorldError(source, path_of(f.section, f.name), "must be finite");
    if (d < f.lo || d > f.hi || (f.above && d <= f.lo)) {
      std::ostringstream range;
      range << "must be " << (f.above ? "above " : "at least ") << f.lo << " and at most " << f.hi;
      throw worlds::WorldError(source, path_of(f.section, f.name), range.str());
    }
    f.set(c, d);
  }
  for (const Field& f : int_fields()) {
    const json* v = lookup(f.section, f.name);
    if (!v) continue;
    if (!v->is_number_integer() ||
        (v->is_number_unsigned() && v->get<std::uint64_t>() > 1000000000ULL) ||
        v->get<std::int64_t>() < static_cast<std::int64_t>(f.lo) ||
        v->get<std::int64_t>() > static_cast<std::int64_t>(f.hi))
      throw worlds::WorldError(source, path_of(f.section, f.name),
                               "expected a whole number from " +
                                   std::to_string(static_cast<int>(f.lo)) + " to " +
                                   std::to_string(static_cast<int>(f.hi)));
    f.set(c, v->get<int>());
  }
  for (const Field& f : bool_fields()) {
    const json* v = lookup(f.section, f.name);
    if (!v) continue;
    if (!v->is_boolean())
      throw worlds::WorldError(source, path_of(f.section, f.name), "expected true or false");
    f.set(c, v->get<bool>() ? 1.0 : 0.0);
  }
}

void read_modes(ConfigLookup& lookup, const std::string& source, EpisodeConfig& c) {
  if (const json* v = lookup("perception", "mode")) {
    const std::string m = v->is_string() ? v->get<std::string>() : "";
    if (m == "sensors")
      c.perception.mode = PerceptionMode::kSensors;
    else if (m == "oracle")
      c.perception.mode = PerceptionMode::kOracle;
    else
      throw worlds::WorldError(source, "perception.mode", "expected \"sensors\" or \"oracle\"");
  }
  if (const json* v = lookup("localization", "estimator")) {
    const std::string e = v->is_string() ? v->get<std::string>() : "";
    if (e == "ekf")
      c.perception.estimator = robot::EstimatorKind::kEkf;
    else if (e == "particles")
      c.perception.estimator = robot::EstimatorKind::kParticles;
    else
      throw worlds::WorldError(source, "localization.estimator",
                               "expected \"ekf\" or \"particles\"");
  }
  if (const json* v = lookup("", "travel")) {
    const std::string t = v->is_string() ? v->get<std::string>() : "";
    if (t == "path")
      c.travel = TravelMode::kPath;
    else if (t == "potential-field")
      c.travel = TravelMode::kPotentialField;
    else
      throw worlds::WorldError(source, "travel", "expected \"path\" or \"potential-field\"");
  }
  if (const json* v = lookup("", "seed")) {
    if (!v->is_number_unsigned())
      throw worlds::WorldError(source, "seed", "expected a whole number");
    c.seed = v->get<std::uint64_t>();
  }
}

/// Values each in range that do not fit together.
void check_consistency(const std::string& source, const EpisodeConfig& c) {
  if (c.kidnap.distance_min_m > c.kidnap.distance_max_m)
    throw worlds::WorldError(source, "kidnap.distance_min_m", "must not exceed distance_max_m");
  if (c.field.k_att <= 0)
    throw worlds::WorldError(source, "potential_field.k_att", "must be positive");
  if (c.field.rho0_m <= c.field.rho_min_m)
    throw worlds::WorldError(source, "potential_field.rho0_m", "must exceed rho_min_m");
  if (c.field.slow_force_ratio <= 0)
    throw worlds::WorldError(source, "potential_field.slow_force_ratio", "must be positive");
  if (c.pursuit_replan_period_s <= 0)
    throw worlds::WorldError(source, "pursuit.replan_period_s", "must be positive");
  if (c.perception.mode == PerceptionMode::kSensors && c.localization.period_s > 0)
    throw worlds::WorldError(source, "localization.period_s",
                             "true-pose fixes exist only in perception.mode \"oracle\" (sensors "
                             "mode localises with the EKF)");
  if (c.perception.particles.min_particles > c.perception.particles.max_particles)
    throw worlds::WorldError(source, "particles.min_particles", "must not exceed max_particles");
  if (c.lidar.min_range_m >= c.lidar.max_range_m)
    throw worlds::WorldError(source, "lidar.min_range_m", "must be below lidar.max_range_m");
  if (c.tracking.lookahead_min_m > c.tracking.lookahead_max_m)
    throw worlds::WorldError(source, "tracking.lookahead_min_m", "must not exceed lookahead_max_m");
  // Each value in range can still ask for too much together: work is bounded, not only input.
  if (const double steps = std::ceil(c.timeout_s / c.step.dt_s);
      steps > static_cast<double>(kMaxEpisodeSteps))
    throw worlds::WorldError(
        source, "timeout_s",
        "timeout_s / step.dt_s asks for " + std::to_string(static_cast<long long>(steps)) +
            " physics steps, more than the limit of " + std::to_string(kMaxEpisodeSteps) +
            " (docs/config.md): shorten the timeout or lengthen the step");
}

}  // namespace

EpisodeConfig parse_episode_config(const std::string& text, const std::string& source,
                                   EpisodeConfig c) {
  const json doc = worlds::parse_json_input(text, source);
  if (!doc.is_object()) throw worlds::WorldError(source, "", "expected a JSON object");
  ConfigLookup lookup(doc, source);
  read_tables(lookup, source, c);
  read_modes(lookup, source, c);
  lookup.refuse_unknown();
  check_consistency(source, c);
  return c;
}

EpisodeConfig load_episode_config(const std::string& path, EpisodeConfig base) {
  std::string text;
  try {
    text = util::read_input_file(path, 16u << 20);
  } catch (const util::InputFileError& e) {
    throw worlds::WorldError(path, "", e.what());
  }
  return parse_episode_config(text, path, base);
}

std::vector<NumberParameter> number_parameters() {
  const EpisodeConfig defaults;
  std::vector<NumberParameter> out;
  auto add = [&](const Field& f, bool whole) {
    out.push_back({f.path(), f.lo, f.hi, f.above, whole, f.get(defaults)});
  };
  for (const Field& f : fields()) add(f, false);
  for (const Field& f : int_fields()) add(f, true);
  return out;
}

NumberParameter number_parameter(const std::string& path) {
  std::vector<std::string> known;
  for (const NumberParameter& p : number_parameters()) {
    if (p.path == path) return p;
    known.push_back(p.path);
  }
  throw std::invalid_argument("'" + path + "': " + worlds::unknown_key_problem(path, known) +
                              " (a number parameter of docs/config.md, as section.key)");
}

std::string default_config_json() { return config_json(EpisodeConfig{}); }

std::string config_json(const EpisodeConfig& c) {
  nlohmann::ordered_json j;
  for (const Field& f : fields()) {
    if (std::string(f.section).empty())
      j[f.name] = f.get(c);
    else
      j[f.section][f.name] = f.get(c);
  }
  for (const Field& f : int_fields()) j[f.section][f.name] = static_cast<int>(f.get(c));
  for (const Field& f : bool_fields()) j[f.section][f.name] = f.get(c) != 0;
  j["perception"]["mode"] = std::string(to_string(c.perception.mode));
  j["localization"]["estimator"] = std::string(to_string(c.perception.estimator));
  j["travel"] = std::string(to_string(c.travel));
  j["seed"] = c.seed;
  return j.dump(2) + "\n";
}

}  // namespace plantsim::episode
