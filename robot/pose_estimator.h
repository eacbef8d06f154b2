// The robot's pose estimator as perception uses it, whichever method it is (an EKF with global
// scan matching, or a particle filter: `localization.estimator`), and what it reports about its
// own health. Robot side: odometry, gyro and lidar readings and the map, never the truth.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "geometry/vec2.h"
#include "robot/readings.h"

namespace plantsim::robot {

enum class LocalizationHealth { kOk, kDegraded, kLost };  ///< in order of severity
std::string_view to_string(LocalizationHealth h);

class PoseEstimator {
 public:
  virtual ~PoseEstimator() = default;

  /// Motion since the last call: the encoders' travel along the heading and the gyro's rate.
  virtual void predict(double distance_m, double gyro_yaw_rate_radps, double dt_s) = 0;
  /// In place of predict when the wheels did not turn since the last reading: a robot at rest
  /// does not turn either, so the gyro reads its bias plus noise, a measurement of the bias (a
  /// zero-velocity update) and not a turn. (Integrated as a turn as well, each reading counted
  /// twice: once for the bias, and again through the heading the scans hold still, and the bias
  /// looked surer than it was.) A reading too far from the bias to be its noise is a robot
  /// turning on wheels that do not (sliding, or moved): that is taken as motion, as predict.
  virtual void standstill(double gyro_yaw_rate_radps, double dt_s) = 0;
  /// One scan, matched to the map (and, when the estimate is wide or contradicted, globally).
  virtual void observe(const LidarScan& scan) = 0;
  /// Moved by something the encoders cannot see (a contact, scans the map stopped explaining):
  /// the position and heading uncertainty grow by these (independent additions).
  virtual void widen(double position_sigma_m, double yaw_sigma_rad) = 0;

  virtual geom::Pose2 pose() const = 0;
  virtual Eigen::Matrix3d pose_covariance() const = 0;
  /// Largest 1-sigma position error along any direction.
  virtual double position_sigma_m() const = 0;
  virtual double yaw_sigma_rad() const = 0;
  virtual double gyro_bias_radps() const = 0;
  /// The lidar's range noise the estimator uses: the larger of the told and the learnt.
  virtual double range_sigma_m() const = 0;
  virtual LocalizationHealth health() const = 0;
  /// Informative scans in a row the map did not explain at the estimate.
  virtual int failed_matches() const = 0;
  /// Lost where the scans see the plant but fit it nowhere: the robot should stop and look.
  virtual bool lost_in_view() const = 0;
  /// Times the estimate was restarted (or reseeded) from a global scan match.
  virtual int relocalizations() const = 0;
};

}  // namespace plantsim::robot
