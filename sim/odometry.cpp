// Dead reckoning with midpoint integration of the measured twist.
#include "sim/odometry.h"

#include <cmath>

namespace plantsim::sim {

Odometry::Odometry(geom::Pose2 start, double wheel_base_m, OdometryNoise noise, std::uint64_t seed)
    : pose_(start), wheel_base_m_(wheel_base_m), noise_(noise), draws_(seed) {}

void Odometry::read() {
  if (counted_s_ <= 0) return;
  double left = left_m_, right = right_m_;
  if (noise_.wheel_speed_noise > 0) {
    left *= 1.0 + noise_.wheel_speed_noise * draws_.gaussian();
    right *= 1.0 + noise_.wheel_speed_noise * draws_.gaussian();
  }
  left *= 1.0 + noise_.left_scale_error;
  right *= 1.0 + noise_.right_scale_error;
  const double distance = 0.5 * (left + right), turn = (right - left) / wheel_base_m_;
  const double mid_yaw = pose_.yaw + 0.5 * turn;
  pose_.x += distance * std::cos(mid_yaw);
  pose_.y += distance * std::sin(mid_yaw);
  pose_.yaw = geom::wrap_angle(pose_.yaw + turn);
  speed_ = distance / counted_s_;
  left_m_ = right_m_ = counted_s_ = 0;
}

}  // namespace plantsim::sim
