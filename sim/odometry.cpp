// Dead reckoning with midpoint integration of the measured twist.
#include "sim/odometry.h"

#include <cmath>

namespace plantsim::sim {

Odometry::Odometry(geom::Pose2 start, double wheel_base_m, OdometryNoise noise, std::uint64_t seed)
    : pose_(start), wheel_base_m_(wheel_base_m), noise_(noise), rng_(seed) {}

void Odometry::update(controller::WheelSpeeds enc, double dt_s) {
  if (noise_.wheel_speed_noise > 0) {
    enc.left_mps *= 1.0 + noise_.wheel_speed_noise * gauss_(rng_);
    enc.right_mps *= 1.0 + noise_.wheel_speed_noise * gauss_(rng_);
  }
  enc.left_mps *= 1.0 + noise_.left_scale_error;
  enc.right_mps *= 1.0 + noise_.right_scale_error;
  const controller::Twist t = controller::to_twist(enc, wheel_base_m_);
  const double mid_yaw = pose_.yaw + 0.5 * t.omega_radps * dt_s;
  pose_.x += t.v_mps * std::cos(mid_yaw) * dt_s;
  pose_.y += t.v_mps * std::sin(mid_yaw) * dt_s;
  pose_.yaw = geom::wrap_angle(pose_.yaw + t.omega_radps * dt_s);
  speed_ = t.v_mps;
}

}  // namespace plantsim::sim
