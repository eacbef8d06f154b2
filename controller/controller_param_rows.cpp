// The controllers' configuration rows: each parameter's section, key and valid range.
#include "controller/controller_param_rows.h"

#include <cmath>

namespace plantsim::controller {

using util::kMaxParameter;

const util::ParamRows<PurePursuitParams>& pure_pursuit_param_rows() {
  static const util::ParamRows<PurePursuitParams> rows = {
      PLANTSIM_PARAM("tracking", lookahead_min_m, "lookahead_min_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", lookahead_max_m, "lookahead_max_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", lookahead_time_s, "lookahead_time_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", sharp_turn_rad, "sharp_turn_rad", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", corner_release_m, "corner_release_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", max_linear_speed_mps, "max_linear_speed_mps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", max_angular_speed_radps, "max_angular_speed_radps", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("tracking", min_approach_speed_mps, "min_approach_speed_mps", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("tracking", approach_slowdown_distance_m, "approach_slowdown_distance_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("tracking", regulated_min_radius_m, "regulated_min_radius_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("tracking", rotate_in_place_threshold_rad, "rotate_in_place_threshold_rad",
                     0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", rotate_in_place_exit_rad, "rotate_in_place_exit_rad", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("tracking", rotate_in_place_speed_radps, "rotate_in_place_speed_radps", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("tracking", goal_tolerance_m, "goal_tolerance_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracking", progress_window_m, "progress_window_m", 0.0, kMaxParameter),
  };
  return rows;
}
const util::ParamRows<DockingParams>& docking_param_rows() {
  static const util::ParamRows<DockingParams> rows = {
      PLANTSIM_PARAM("docking", approach_speed_mps, "approach_speed_mps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", approach_lookahead_m, "approach_lookahead_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", align_tolerance_rad, "align_tolerance_rad", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", align_speed_radps, "align_speed_radps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", backoff_speed_mps, "backoff_speed_mps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", overshoot_limit_m, "overshoot_limit_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", filter.detection_blend, "detection_blend", 0.0, 1.0),
      PLANTSIM_PARAM_ABOVE("docking", filter.detection_gate_m, "detection_gate_m", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM("docking", approach_timeout_s, "approach_timeout_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", guard.safety_margin_m, "safety_margin_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", guard.max_decel_mps2, "max_decel_mps2", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", guard.check_extra_m, "check_extra_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", travel.replan_after_s, "replan_after_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", yield.yield_horizon_s, "yield_horizon_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", yield.yield_speed_mps, "yield_speed_mps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", yield.bystander_reach_m, "bystander_reach_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", yield.bystander_max_size_m, "bystander_max_size_m", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("docking", yield.bystander_wait_s, "bystander_wait_s", 0.0, 86400.0),
      PLANTSIM_PARAM("docking", travel.confident_sigma_m, "confident_sigma_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", travel.uncertain_sigma_m, "uncertain_sigma_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", travel.uncertain_speed_fraction, "uncertain_speed_fraction", 0.0,
                     1.0),
      PLANTSIM_PARAM_ABOVE("docking", press_speed_mps, "press_speed_mps", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("docking", press_timeout_s, "press_timeout_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("docking", stuck_timeout_s, "stuck_timeout_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("docking", settle_s, "settle_s", 0.0, 60.0),
      PLANTSIM_PARAM_ABOVE("docking", relocalize_timeout_s, "relocalize_timeout_s", 0.0, 86400.0),
      PLANTSIM_PARAM("docking", max_retries, "max_retries", 0, 1000),
      PLANTSIM_PARAM("docking", undock, "undock", 0, 1),
  };
  return rows;
}
const util::ParamRows<TractionParams>& traction_param_rows() {
  static const util::ParamRows<TractionParams> rows = {
      PLANTSIM_PARAM_ABOVE("traction", max_accel_mps2, "max_accel_mps2", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("traction", max_angular_accel_radps2, "max_angular_accel_radps2", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM("traction", slip_scale_factor, "slip_scale_factor", 0.0, 1.0),
      PLANTSIM_PARAM("traction", min_scale, "min_scale", 0.0, 1.0),
      PLANTSIM_PARAM("traction", slip_hold_s, "slip_hold_s", 0.0, 60.0),
      PLANTSIM_PARAM("traction", recover_per_s, "recover_per_s", 0.0, 10.0),
      PLANTSIM_PARAM("traction", creep_mps, "creep_mps", 0.0, 10.0),
      PLANTSIM_PARAM("traction", creep_radps, "creep_radps", 0.0, 10.0),
      PLANTSIM_PARAM("traction", full_grip_accel_mps2, "full_grip_accel_mps2", 0.0, kMaxParameter),
      PLANTSIM_PARAM("traction", enabled, "enabled", 0, 1),
      PLANTSIM_PARAM("traction", stop_within_sight, "stop_within_sight", 0, 1),
      PLANTSIM_PARAM_ABOVE("traction", stop_decel_mps2, "stop_decel_mps2", 0.0, 100.0),
      PLANTSIM_PARAM("traction", stop_margin_m, "stop_margin_m", 0.0, 10.0),
      PLANTSIM_PARAM("traction", stop_reaction_s, "stop_reaction_s", 0.0, 10.0),
  };
  return rows;
}
const util::ParamRows<PotentialFieldParams>& potential_field_param_rows() {
  static const util::ParamRows<PotentialFieldParams> rows = {
      PLANTSIM_PARAM("potential_field", k_att, "k_att", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", m, "m", 0.0, 10.0),
      PLANTSIM_PARAM("potential_field", k_att_v, "k_att_v", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", m_v, "m_v", 0.0, 10.0),
      PLANTSIM_PARAM("potential_field", k_rep, "k_rep", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", n, "n", 0.0, 10.0),
      PLANTSIM_PARAM("potential_field", rho0_m, "rho0_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", k_rep_v, "k_rep_v", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", n_v, "n_v", 0.0, 10.0),
      PLANTSIM_PARAM("potential_field", rho_min_m, "rho_min_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", max_speed_mps, "max_speed_mps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", turn_gain, "turn_gain", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", max_angular_speed_radps, "max_angular_speed_radps", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("potential_field", max_decel_mps2, "max_decel_mps2", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", arrive_radius_m, "arrive_radius_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", slow_force_ratio, "slow_force_ratio", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", balance_ratio, "balance_ratio", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", stall_window_s, "stall_window_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", stall_distance_m, "stall_distance_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", wall_distance_m, "wall_distance_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", wall_gain, "wall_gain", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", follow_angle_rad, "follow_angle_rad", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", leave_margin_m, "leave_margin_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", sensor_range_m, "sensor_range_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("potential_field", max_wall_follows, "max_wall_follows", 0, 1000),
  };
  return rows;
}
}  // namespace plantsim::controller
