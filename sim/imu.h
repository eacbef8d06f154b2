// The IMU's gyro: yaw rate with a constant turn-on bias (drawn once per episode), a slow bias
// random walk and white noise per sample. Read at the control rate from the body's true yaw
// rate (sensors see the real motion; wheel slip shows here and not in the encoders).
#pragma once

#include <cstdint>

#include "util/random_stream.h"

namespace plantsim::sim {

/// Defaults: a consumer MEMS gyro after factory calibration.
struct ImuParams {
  double yaw_rate_noise_radps = 0.002;         ///< std-dev of each sample's white noise
  double bias_radps = 0.002;                   ///< std-dev of the turn-on bias
  double bias_walk_radps_per_sqrt_s = 0.0001;  ///< bias random walk
};

class Imu {
 public:
  Imu(ImuParams params, std::uint64_t seed);
  /// One sample: the true yaw rate as the gyro reports it, `dt_s` after the previous one.
  double read_yaw_rate(double true_yaw_rate_radps, double dt_s);

 private:
  ImuParams params_;
  util::RandomStream noise_;
  double bias_radps_;
};

}  // namespace plantsim::sim
