// Gyro bias and noise.
#include "sim/imu.h"

#include <algorithm>
#include <cmath>

namespace plantsim::sim {

Imu::Imu(ImuParams params, std::uint64_t seed)
    : params_(params), noise_(seed ^ 0x3c6ef372fe94f82bULL) {
  bias_radps_ = params_.bias_radps * noise_.gaussian();
}

double Imu::read_yaw_rate(double true_yaw_rate_radps, double dt_s) {
  bias_radps_ +=
      params_.bias_walk_radps_per_sqrt_s * std::sqrt(std::max(dt_s, 0.0)) * noise_.gaussian();
  return true_yaw_rate_radps + bias_radps_ + params_.yaw_rate_noise_radps * noise_.gaussian();
}

}  // namespace plantsim::sim
