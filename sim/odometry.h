// Wheel odometry: dead reckoning from the encoders, with configurable noise (random per
// reading, proportional to speed) and slip (a constant scale error of each wheel, as from a
// worn tyre). Like real encoders, wheel travel is counted every physics step and the pose is
// integrated when the controller reads it. The estimate drifts; the ground truth is kept
// elsewhere, for metrics.
#pragma once

#include "controller/diff_drive.h"
#include "geometry/vec2.h"
#include "util/random_stream.h"

namespace plantsim::sim {

struct OdometryNoise {
  double wheel_speed_noise = 0.0;  ///< std-dev of the relative error per wheel per step
  double left_scale_error = 0.0;   ///< systematic relative error of the left wheel
  double right_scale_error = 0.0;  ///< systematic relative error of the right wheel
};

class Odometry {
 public:
  Odometry(geom::Pose2 start, double wheel_base_m, OdometryNoise noise, std::uint64_t seed);
  /// Counts one physics step of wheel travel at the encoders' rim speeds.
  void count(controller::WheelSpeeds encoders, double dt_s) {
    left_m_ += encoders.left_mps * dt_s;
    right_m_ += encoders.right_mps * dt_s;
    counted_s_ += dt_s;
  }
  /// Integrates the travel counted since the last read into the pose.
  void read();
  const geom::Pose2& pose() const { return pose_; }
  double speed_mps() const { return speed_; }

 private:
  geom::Pose2 pose_;
  double wheel_base_m_;
  OdometryNoise noise_;
  util::RandomStream draws_;
  double speed_ = 0;
  double left_m_ = 0, right_m_ = 0, counted_s_ = 0;
};

}  // namespace plantsim::sim
