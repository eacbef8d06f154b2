// Wheel odometry: dead reckoning from the encoders' rim speeds, with configurable noise
// (random per step, proportional to speed) and slip (a constant scale error of each wheel,
// as from a worn tyre). The estimate drifts; the ground truth is kept elsewhere, for metrics.
#pragma once

#include <random>

#include "controller/diff_drive.h"
#include "geometry/vec2.h"

namespace plantsim::sim {

struct OdometryNoise {
  double wheel_speed_noise = 0.0;    ///< std-dev of the relative error per wheel per step
  double left_scale_error = 0.0;     ///< systematic relative error of the left wheel
  double right_scale_error = 0.0;    ///< systematic relative error of the right wheel
};

class Odometry {
 public:
  Odometry(geom::Pose2 start, double wheel_base_m, OdometryNoise noise, std::uint64_t seed);
  void update(controller::WheelSpeeds encoders, double dt_s);
  const geom::Pose2& pose() const { return pose_; }
  double speed_mps() const { return speed_; }

 private:
  geom::Pose2 pose_;
  double wheel_base_m_;
  OdometryNoise noise_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> gauss_{0.0, 1.0};
  double speed_ = 0;
};

}  // namespace plantsim::sim
