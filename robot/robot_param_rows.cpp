// The robot side's configuration rows: each parameter's section, key and valid range.
#include "robot/robot_param_rows.h"

#include <cmath>

namespace plantsim::robot {

using util::kMaxParameter;

const util::ParamRows<EkfParams>& ekf_param_rows() {
  static const util::ParamRows<EkfParams> rows = {
      PLANTSIM_PARAM_ABOVE("ekf", initial_position_sigma_m, "initial_position_sigma_m", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", initial_yaw_sigma_rad, "initial_yaw_sigma_rad", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", initial_bias_sigma_radps, "initial_bias_sigma_radps", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM("ekf", distance_noise, "distance_noise", 0.0, kMaxParameter),
      PLANTSIM_PARAM("ekf", lateral_noise, "lateral_noise", 0.0, kMaxParameter),
      PLANTSIM_PARAM("ekf", gyro_noise_radps, "gyro_noise_radps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("ekf", bias_walk_radps_per_sqrt_s, "bias_walk_radps_per_sqrt_s", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", range_sigma_m, "range_sigma_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", gate_chi2, "gate_chi2", 0.0, kMaxParameter),
      PLANTSIM_PARAM("ekf", min_incidence_cos, "min_incidence_cos", 0.0, 1.0),
      PLANTSIM_PARAM("ekf", range_learning_rate, "range_learning_rate", 0.0, 1.0),
      PLANTSIM_PARAM("ekf", gyro_learning_rate, "gyro_learning_rate", 0.0, 1.0),
      PLANTSIM_PARAM("ekf", gate_floor_m, "gate_floor_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", constraint_sigma_m, "constraint_sigma_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("ekf", degraded_inlier_fraction, "degraded_inlier_fraction", 0.0, 1.0),
      PLANTSIM_PARAM_ABOVE("ekf", ok_position_sigma_m, "ok_position_sigma_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", nis_quantile_z, "nis_quantile_z", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("ekf", lost_position_sigma_m, "lost_position_sigma_m", 0.0,
                           kMaxParameter),
      PLANTSIM_PARAM("ekf", beams_used, "beams_used", 1, 10000),
      PLANTSIM_PARAM("ekf", iterations, "iterations", 1, 20),
      PLANTSIM_PARAM("ekf", min_informative_beams, "min_informative_beams", 3, 10000),
      PLANTSIM_PARAM("ekf", nis_window, "nis_window", 1, 1000),
      PLANTSIM_PARAM("ekf", lost_failed_matches, "lost_failed_matches", 1, 100000),
      PLANTSIM_PARAM("ekf", gyro_min_samples, "gyro_min_samples", 1, 100000),
      PLANTSIM_PARAM("ekf", learn_noise, "learn_noise", 0, 1),
  };
  return rows;
}
const util::ParamRows<TrackerParams>& tracker_param_rows() {
  static const util::ParamRows<TrackerParams> rows = {
      PLANTSIM_PARAM("tracker", unexplained_margin_m, "unexplained_margin_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("tracker", range_m, "range_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("tracker", cluster_gap_m, "cluster_gap_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("tracker", association_gate_m, "association_gate_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracker", alpha, "alpha", 0.0, 1.0),
      PLANTSIM_PARAM("tracker", beta, "beta", 0.0, 1.0),
      PLANTSIM_PARAM_ABOVE("tracker", max_speed_mps, "max_speed_mps", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracker", still_speed_mps, "still_speed_mps", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("tracker", forget_after_s, "forget_after_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracker", min_size_m, "min_size_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tracker", assumed_depth_m, "assumed_depth_m", 0.0, kMaxParameter),
  };
  return rows;
}
const util::ParamRows<ObstacleLayerParams>& layer_param_rows() {
  static const util::ParamRows<ObstacleLayerParams> rows = {
      PLANTSIM_PARAM_ABOVE("layer", cell_m, "cell_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("layer", clear_range_m, "clear_range_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("layer", enabled, "enabled", 0, 1),
  };
  return rows;
}
const util::ParamRows<ParticleParams>& particle_param_rows() {
  static const util::ParamRows<ParticleParams> rows = {
      PLANTSIM_PARAM_ABOVE("particles", kld.kld_error, "kld_error", 0.0, 1.0),
      PLANTSIM_PARAM_ABOVE("particles", kld.kld_z, "kld_z", 0.0, 10.0),
      PLANTSIM_PARAM_ABOVE("particles", kld.bin_xy_m, "bin_xy_m", 0.0, 100.0),
      PLANTSIM_PARAM_ABOVE("particles", kld.bin_yaw_rad, "bin_yaw_rad", 0.0, M_PI),
      PLANTSIM_PARAM("particles", field.z_hit, "z_hit", 0.0, 1.0),
      PLANTSIM_PARAM_ABOVE("particles", field.z_rand, "z_rand", 0.0, 1.0),
      PLANTSIM_PARAM("particles", field.field_sigma_m, "field_sigma_m", 0.0, 10.0),
      PLANTSIM_PARAM("particles", field.unsettled_sigma_m, "unsettled_sigma_m", 0.0, 10.0),
      PLANTSIM_PARAM_ABOVE("particles", field.field_resolution_m, "field_resolution_m", 0.0, 10.0),
      PLANTSIM_PARAM("particles", update_min_m, "update_min_m", 0.0, 100.0),
      PLANTSIM_PARAM("particles", update_min_rad, "update_min_rad", 0.0, M_PI),
      PLANTSIM_PARAM("particles", recovery.alpha_slow, "alpha_slow", 0.0, 1.0),
      PLANTSIM_PARAM("particles", recovery.alpha_fast, "alpha_fast", 0.0, 1.0),
      PLANTSIM_PARAM("particles", kld.jitter_m, "jitter_m", 0.0, 10.0),
      PLANTSIM_PARAM("particles", kld.jitter_rad, "jitter_rad", 0.0, M_PI),
      PLANTSIM_PARAM("particles", contradicted_agreement, "contradicted_agreement", 0.0, 1.0),
      PLANTSIM_PARAM("particles", recovery.reseed_fraction, "reseed_fraction", 0.0, 0.9),
      PLANTSIM_PARAM_ABOVE("particles", search.reseed_tile_m, "reseed_tile_m", 0.0, 50.0),
      PLANTSIM_PARAM("particles", min_explained, "min_explained", 0.0, 1.0),
      PLANTSIM_PARAM("particles", confirm.confirm_turn_rad, "confirm_turn_rad", 0.0, 100.0),
      PLANTSIM_PARAM("particles", confirm.confirm_move_m, "confirm_move_m", 0.0, 1000.0),
      PLANTSIM_PARAM("particles", confirm.rival_margin, "rival_margin", 0.0, 1e6),
      PLANTSIM_PARAM("particles", confirm.place_offset_m, "place_offset_m", 0.0, 100.0),
      PLANTSIM_PARAM("particles", kld.min_particles, "min_particles", 1, 100000),
      PLANTSIM_PARAM("particles", kld.max_particles, "max_particles", 1, 100000),
      PLANTSIM_PARAM("particles", field.beams, "beams", 1, 10000),
      PLANTSIM_PARAM("particles", search.reseed_rings, "reseed_rings", 1, 10),
      PLANTSIM_PARAM("particles", min_returns, "min_returns", 1, 100000),
      PLANTSIM_PARAM("particles", confirm.confirm_strikes, "confirm_strikes", 1, 1000),
      PLANTSIM_PARAM("particles", search.max_places, "max_places", 1, 1000),
      PLANTSIM_PARAM("particles", view_change_returns, "view_change_returns", 1, 100000),
      PLANTSIM_PARAM("particles", view_change_lost_scans, "view_change_lost_scans", 1, 100000),
      PLANTSIM_PARAM("particles", seed, "seed", 0, 1000000000),
      PLANTSIM_PARAM("particles", motion.distance_noise, "motion_distance_noise", 0.0,
                     kMaxParameter),
      PLANTSIM_PARAM("particles", motion.lateral_noise, "motion_lateral_noise", 0.0, kMaxParameter),
      PLANTSIM_PARAM("particles", motion.bias_walk_radps_per_sqrt_s,
                     "motion_bias_walk_radps_per_sqrt_s", 0.0, kMaxParameter),
  };
  return rows;
}
const util::ParamRows<LostSearchParams>& lost_search_param_rows() {
  static const util::ParamRows<LostSearchParams> rows = {
      PLANTSIM_PARAM_ABOVE("lost_search", speed_mps, "speed_mps", 0.0, 5.0),
      PLANTSIM_PARAM_ABOVE("lost_search", turn_radps, "turn_radps", 0.0, 10.0),
      PLANTSIM_PARAM_ABOVE("lost_search", leg_m, "leg_m", 0.0, 1000.0),
      PLANTSIM_PARAM("lost_search", clearance_m, "clearance_m", 0.0, 10.0),
      PLANTSIM_PARAM("lost_search", narrow_clearance_m, "narrow_clearance_m", 0.0, 10.0),
      PLANTSIM_PARAM("lost_search", standoff_m, "standoff_m", 0.0, 100.0),
      PLANTSIM_PARAM_ABOVE("lost_search", surface_reach_m, "surface_reach_m", 0.0, 1000.0),
      PLANTSIM_PARAM("lost_search", enabled, "enabled", 0, 1),
  };
  return rows;
}
const util::ParamRows<CoastalParams>& coastal_param_rows() {
  static const util::ParamRows<CoastalParams> rows = {
      PLANTSIM_PARAM_ABOVE("coastal", sight_fraction, "sight_fraction", 0.0, 1.0),
      PLANTSIM_PARAM("coastal", activate_blind_m, "activate_blind_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("coastal", blind_scale_m, "blind_scale_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("coastal", node_spacing_m, "node_spacing_m", 0.1, kMaxParameter),
      PLANTSIM_PARAM("coastal", max_nodes, "max_nodes", 2, 100000),
      PLANTSIM_PARAM("coastal", enabled, "enabled", 0, 1),
  };
  return rows;
}
const util::ParamRows<PerceptionParams>& perception_param_rows() {
  static const util::ParamRows<PerceptionParams> rows = [] {
    util::ParamRows<PerceptionParams> own = {
        PLANTSIM_PARAM("perception", target_exclusion_m, "target_exclusion_m", 0.0, kMaxParameter),
        PLANTSIM_PARAM("perception", range_m, "range_m", 0.0, kMaxParameter),
        PLANTSIM_PARAM("perception", moving_speed_mps, "moving_speed_mps", 0.0, kMaxParameter),
        PLANTSIM_PARAM("perception", explained_sigmas, "explained_sigmas", 0.0, kMaxParameter),
        PLANTSIM_PARAM("perception", gyro_calibration_s, "gyro_calibration_s", 0.0, kMaxParameter),
        PLANTSIM_PARAM_ABOVE("perception", displaced_jump_m, "displaced_jump_m", 0.0,
                             kMaxParameter),
        PLANTSIM_PARAM_ABOVE("perception", slip_jump_m, "slip_jump_m", 0.0, kMaxParameter),
        PLANTSIM_PARAM_ABOVE("perception", slip_turn_radps, "slip_turn_radps", 0.0, kMaxParameter),
        PLANTSIM_PARAM("perception", relocalize_sigma_m, "relocalize_sigma_m", 0.0, 10.0),
        PLANTSIM_PARAM_ABOVE("perception", slip_window_s, "slip_window_s", 0.0, 10.0),
    };
    const util::ParamRows<GlobalMatchParams> global = {
        PLANTSIM_PARAM_ABOVE("perception", global_match_sigma_m, "global_match_sigma_m", 0.0,
                             100.0),
        PLANTSIM_PARAM("perception", global_match_period_s, "global_match_period_s", 0.0, 100.0),
        PLANTSIM_PARAM("perception", global_match_max_window_m, "global_match_max_window_m", 0.1,
                       100.0),
        PLANTSIM_PARAM("perception", verify_agreement, "global_match_verify_agreement", 0.0, 1.0),
    };
    util::append_rows_of_part(own, global, PLANTSIM_PART(global));
    return own;
  }();
  return rows;
}

const util::ChoiceRows<PerceptionParams>& perception_choice_rows() {
  static const util::ChoiceRows<PerceptionParams> rows = {
      PLANTSIM_CHOICE("perception", mode, "mode", PerceptionMode,
                      {"sensors", PerceptionMode::kSensors}, {"oracle", PerceptionMode::kOracle}),
  };
  return rows;
}

}  // namespace plantsim::robot
