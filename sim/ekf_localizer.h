// Localisation that estimates: an extended Kalman filter over the pose on the map and the
// gyro's bias, x = [x, y, yaw, b]. It predicts from the encoders' travel and the gyro's yaw
// rate, and corrects with each lidar scan matched to the map: every used beam's range is
// compared with the range the map predicts from the estimated pose (a ray cast through the
// map), linearised point-to-line at the surface hit, gated by its innovation, and the update
// is iterated (Gauss-Newton) from the prior. Health is judged from what the scans say:
// the share of beams the map explains and the size of the covariance.
#pragma once

#include <Eigen/Dense>

#include <string>
#include <string_view>

#include "geometry/vec2.h"
#include "sim/lidar.h"
#include "sim/map_raycaster.h"

namespace plantsim::sim {

struct EkfParams {
  double initial_position_sigma_m = 0.05;   ///< uncertainty of the start pose the robot is given
  double initial_yaw_sigma_rad = 0.02;
  double initial_bias_sigma_radps = 0.005;  ///< gyro bias, before any correction
  double distance_noise = 0.02;             ///< std-dev of travel per metre travelled (encoders, slip)
  double lateral_noise = 0.007;             ///< sideways skid per radian turned while moving (m/rad)
  double gyro_noise_radps = 0.003;          ///< the gyro's white noise, as the filter assumes it
  double bias_walk_radps_per_sqrt_s = 0.0002;
  double range_sigma_m = 0.015;             ///< per beam (lidar noise plus map error)
  int beams_used = 60;                      ///< beams per scan in the update, spread evenly
  double gate_chi2 = 9.0;                   ///< beams whose innovation exceeds this (normalised) are outliers
  double min_incidence_cos = 0.25;          ///< beams grazing a surface more than this are skipped
  int iterations = 3;
  double degraded_inlier_fraction = 0.3;    ///< a scan the map explains less than this is a failed match
  double lost_position_sigma_m = 0.5;       ///< beyond this 1-sigma the localisation is lost
};

enum class LocalizationHealth { kOk, kDegraded, kLost };  ///< in order of severity
std::string_view to_string(LocalizationHealth h);

class EkfLocalizer {
 public:
  using State = Eigen::Vector4d;
  using Covariance = Eigen::Matrix4d;

  EkfLocalizer(EkfParams params, const geom::Pose2& initial_pose, const MapRaycaster& map);

  /// Motion since the last call: the encoders' travel along the heading and the gyro's rate.
  void predict(double distance_m, double gyro_yaw_rate_radps, double dt_s);
  /// One scan matched to the map. Returns the share of used beams the map explained.
  double correct(const LidarScan& scan);

  geom::Pose2 pose() const { return {x_(0), x_(1), x_(2)}; }
  const Covariance& covariance() const { return P_; }
  Eigen::Matrix3d pose_covariance() const { return P_.topLeftCorner<3, 3>(); }
  /// Largest 1-sigma position error along any direction.
  double position_sigma_m() const;
  /// Widens the position and heading uncertainty (independent additions): after the robot was
  /// moved by something its encoders cannot see, so that the scans can pull the estimate there.
  void widen(double position_sigma_m, double yaw_sigma_rad);
  double yaw_sigma_rad() const { return std::sqrt(P_(2, 2)); }
  double gyro_bias_radps() const { return x_(3); }
  LocalizationHealth health() const { return health_; }
  int failed_matches() const { return failed_matches_; }

 private:
  void update_health();
  EkfParams p_;
  const MapRaycaster& map_;
  State x_;
  Covariance P_;
  LocalizationHealth health_ = LocalizationHealth::kOk;
  int failed_matches_ = 0;       // scans in a row the map did not explain
};

}  // namespace plantsim::sim
