// The particle filter's motion model (AMCL's odometry model, for a differential drive with a
// gyro): owns its noise parameters (`particles.motion_*`), the motion summed since the last scan
// and the motion held back from the particles while a settled filter skips scans, and draws
// each particle's own motion from them. The gyro's white noise is the sensor's (told as
// `ekf.gyro_noise_radps`, learnt online by the filter), passed in with each reading.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/vec2.h"
#include "robot/particle_set.h"
#include "util/random_stream.h"

namespace plantsim::robot {

/// The defaults are the EKF's process noise (ekf_localizer.h), which the particle filter used
/// before it had its own.
struct ParticleMotionParams {
  double distance_noise = 0.02;  ///< std-dev of travel per metre travelled (encoders, slip)
  double lateral_noise = 0.007;  ///< sideways skid per radian turned while moving (m/rad)
  double bias_walk_radps_per_sqrt_s = 0.0002;  ///< each particle's gyro bias walks by this
};

/// Motion over a stretch of time, in the frame of the pose it started from.
struct OdometryDelta {
  geom::Pose2 delta;
  double moved_m = 0, turned_rad = 0, gyro_var = 0, time_s = 0;
};

class ParticleMotionModel {
 public:
  explicit ParticleMotionModel(const ParticleMotionParams& params) : p_(params) {}

  /// One reading: `distance_m` along the heading while turning `turn_rad` (the set's mean bias
  /// removed), the gyro's noise `gyro_sigma_radps` over `dt_s`.
  void add(double distance_m, double turn_rad, double gyro_sigma_radps, double dt_s);
  /// The motion since the last scan, and what earlier scans held back from the particles.
  const OdometryDelta& pending() const { return pending_; }
  const OdometryDelta& deferred() const { return deferred_; }
  /// The pending motion held back (the estimate dead-reckons by the returned delta).
  geom::Pose2 defer();
  /// The held-back and pending motion, chained, both cleared: what the particles move by.
  OdometryDelta take();
  /// Each particle moved by `m` with its own noise draws: travel noise along, skid across while
  /// turning on the move, the gyro's white noise; each turns by its own bias (`m` was summed
  /// under the set's mean `mean_bias`), and its bias walks.
  void sample(const OdometryDelta& m, double mean_bias, std::vector<Particle>& set,
              util::RandomStream& rng) const;
  /// `covariance` grown by the motion not yet applied to the particles (`bias_var`: the
  /// spread of the set's biases).
  Eigen::Matrix3d grow(Eigen::Matrix3d covariance, double bias_var) const;

  /// `first` then `then`: the deltas composed, the rest summed.
  static OdometryDelta chain(const OdometryDelta& first, const OdometryDelta& then);

 private:
  ParticleMotionParams p_;
  OdometryDelta pending_;
  OdometryDelta deferred_;  // motion of earlier scans not yet applied to the particles
};

}  // namespace plantsim::robot
