// The simulator's configuration rows: each parameter's section, key and valid range.
#include "sim/sim_param_rows.h"

#include <cmath>

namespace plantsim::sim {

const util::ParamRows<StepSettings>& step_param_rows() {
  static const util::ParamRows<StepSettings> rows = {
      PLANTSIM_PARAM("step", dt_s, "dt_s", 1e-4, 0.1),
      PLANTSIM_PARAM("step", velocity_iterations, "velocity_iterations", 0, 1000),
      PLANTSIM_PARAM("step", position_iterations, "position_iterations", 0, 1000),
  };
  return rows;
}
const util::ParamRows<DriveParams>& drive_param_rows() {
  static const util::ParamRows<DriveParams> rows = {
      PLANTSIM_PARAM("drive", tyre_friction, "tyre_friction", 0.0, kMaxParameter),
  };
  return rows;
}
const util::ParamRows<OdometryNoise>& odometry_param_rows() {
  static const util::ParamRows<OdometryNoise> rows = {
      PLANTSIM_PARAM("odometry", wheel_speed_noise, "wheel_speed_noise", 0.0, kMaxParameter),
      PLANTSIM_PARAM("odometry", left_scale_error, "left_scale_error", -0.5, 0.5),
      PLANTSIM_PARAM("odometry", right_scale_error, "right_scale_error", -0.5, 0.5),
  };
  return rows;
}
const util::ParamRows<LocalizationParams>& localization_param_rows() {
  static const util::ParamRows<LocalizationParams> rows = {
      PLANTSIM_PARAM("localization", period_s, "period_s", 0.0, kMaxParameter),
      PLANTSIM_PARAM("localization", position_noise_m, "position_noise_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("localization", yaw_noise_rad, "yaw_noise_rad", 0.0, kMaxParameter),
  };
  return rows;
}
const util::ParamRows<DetectionParams>& detection_param_rows() {
  static const util::ParamRows<DetectionParams> rows = {
      PLANTSIM_PARAM("detection", range_m, "range_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("detection", field_of_view_rad, "field_of_view_rad", 0.0, kMaxParameter),
      PLANTSIM_PARAM("detection", position_noise_m, "position_noise_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("detection", yaw_noise_rad, "yaw_noise_rad", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("detection", rate_hz, "rate_hz", 0.0, 1000.0),
      PLANTSIM_PARAM("detection", mount_x_m, "mount_x_m", -10.0, 10.0),
      PLANTSIM_PARAM("detection", false_negative_probability, "false_negative_probability", 0.0,
                     1.0),
      PLANTSIM_PARAM("detection", outlier_probability, "outlier_probability", 0.0, 1.0),
      PLANTSIM_PARAM("detection", outlier_position_m, "outlier_position_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("detection", outlier_yaw_rad, "outlier_yaw_rad", 0.0, kMaxParameter),
      PLANTSIM_PARAM("detection", latency_s, "latency_s", 0.0, 1.5),
      PLANTSIM_PARAM("detection", enabled, "enabled", 0, 1),
      PLANTSIM_PARAM("detection", occlusion, "occlusion", 0, 1),
  };
  return rows;
}
const util::ParamRows<LidarParams>& lidar_param_rows() {
  static const util::ParamRows<LidarParams> rows = {
      PLANTSIM_PARAM_ABOVE("lidar", field_of_view_rad, "field_of_view_rad", 0.0, 2.0 * M_PI),
      PLANTSIM_PARAM("lidar", min_range_m, "min_range_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM_ABOVE("lidar", max_range_m, "max_range_m", 0.0, 1000.0),
      PLANTSIM_PARAM_ABOVE("lidar", rate_hz, "rate_hz", 0.0, 1000.0),
      PLANTSIM_PARAM("lidar", mount_x_m, "mount_x_m", -10.0, 10.0),
      PLANTSIM_PARAM("lidar", mount_y_m, "mount_y_m", -10.0, 10.0),
      PLANTSIM_PARAM("lidar", mount_yaw_rad, "mount_yaw_rad", -M_PI, M_PI),
      PLANTSIM_PARAM("lidar", range_noise_m, "range_noise_m", 0.0, 10.0),
      PLANTSIM_PARAM("lidar", dropout_probability, "dropout_probability", 0.0, 1.0),
      PLANTSIM_PARAM("lidar", beam_count, "beam_count", 1, 10000),
      PLANTSIM_PARAM("lidar", enabled, "enabled", 0, 1),
      PLANTSIM_PARAM("lidar", max_range_returns, "max_range_returns", 0, 1),
  };
  return rows;
}
const util::ParamRows<ImuParams>& imu_param_rows() {
  static const util::ParamRows<ImuParams> rows = {
      PLANTSIM_PARAM("imu", yaw_rate_noise_radps, "yaw_rate_noise_radps", 0.0, 10.0),
      PLANTSIM_PARAM("imu", bias_radps, "bias_radps", 0.0, 10.0),
      PLANTSIM_PARAM("imu", bias_walk_radps_per_sqrt_s, "bias_walk_radps_per_sqrt_s", 0.0, 10.0),
  };
  return rows;
}
const util::ParamRows<BeaconParams>& beacon_param_rows() {
  static const util::ParamRows<BeaconParams> rows = {
      PLANTSIM_PARAM("beacon", position_noise_m, "position_noise_m", 0.0, 100.0),
  };
  return rows;
}
const util::ParamRows<ChargerPadParams>& tolerance_param_rows() {
  static const util::ParamRows<ChargerPadParams> rows = {
      PLANTSIM_PARAM("tolerance", lateral_tolerance_m, "position_m", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tolerance", heading_tolerance_rad, "heading_rad", 0.0, kMaxParameter),
      PLANTSIM_PARAM("tolerance", dwell_s, "dwell_s", 0.0, 60.0),
      PLANTSIM_PARAM("tolerance", min_press_m, "min_press_m", 0.0, 0.05),
  };
  return rows;
}
}  // namespace plantsim::sim
