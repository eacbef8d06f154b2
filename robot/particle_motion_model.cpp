// The particle filter's motion model: odometry summed between scans, and each particle's own
// draw of it.
#include "robot/particle_motion_model.h"

#include <algorithm>
#include <cmath>

namespace plantsim::robot {

void ParticleMotionModel::add(double distance_m, double turn_rad, double gyro_sigma_radps,
                              double dt_s) {
  const double mid = pending_.delta.yaw + 0.5 * turn_rad;
  pending_.delta.x += distance_m * std::cos(mid);
  pending_.delta.y += distance_m * std::sin(mid);
  pending_.delta.yaw += turn_rad;
  pending_.moved_m += std::fabs(distance_m);
  pending_.turned_rad += std::fabs(turn_rad);
  const double v = gyro_sigma_radps * dt_s;
  pending_.gyro_var += v * v;
  pending_.time_s += dt_s;
}

OdometryDelta ParticleMotionModel::chain(const OdometryDelta& first, const OdometryDelta& then) {
  OdometryDelta out = then;
  out.delta = geom::compose(first.delta, then.delta);
  out.moved_m += first.moved_m;
  out.turned_rad += first.turned_rad;
  out.gyro_var += first.gyro_var;
  out.time_s += first.time_s;
  return out;
}

geom::Pose2 ParticleMotionModel::defer() {
  const geom::Pose2 delta = pending_.delta;
  deferred_ = chain(deferred_, pending_);
  pending_ = {};
  return delta;
}

OdometryDelta ParticleMotionModel::take() {
  const OdometryDelta m = deferred_.time_s > 0 ? chain(deferred_, pending_) : pending_;
  pending_ = deferred_ = {};
  return m;
}

void ParticleMotionModel::sample(const OdometryDelta& m, double mean_bias,
                                 std::vector<Particle>& set, util::RandomStream& rng) const {
  // As the EKF's model: travel noise along, skid across while turning on the move (the turn
  // counted at most as the travel over 0.1 m), the gyro's white noise.
  const double along = p_.distance_noise * m.moved_m;
  const double across = p_.lateral_noise * std::min(m.turned_rad, m.moved_m / 0.1);
  const double yaw = std::sqrt(m.gyro_var);
  const double walk = p_.bias_walk_radps_per_sqrt_s * std::sqrt(m.time_s);
  const double length = std::hypot(m.delta.x, m.delta.y);
  const geom::Vec2 u =
      length > 1e-9 ? geom::Vec2{m.delta.x / length, m.delta.y / length} : geom::Vec2{1.0, 0.0};
  for (Particle& q : set) {
    const double a = particle_normal(rng, along), c = particle_normal(rng, across);
    const geom::Pose2 d{m.delta.x + a * u.x - c * u.y, m.delta.y + a * u.y + c * u.x,
                        m.delta.yaw - (q.bias - mean_bias) * m.time_s + particle_normal(rng, yaw)};
    q.bias += particle_normal(rng, walk);
    const geom::Pose2 moved = geom::compose({q.x, q.y, q.yaw}, d);
    q.x = moved.x;
    q.y = moved.y;
    q.yaw = geom::wrap_angle(moved.yaw);
  }
}

Eigen::Matrix3d ParticleMotionModel::grow(Eigen::Matrix3d covariance, double bias_var) const {
  const OdometryDelta m = chain(deferred_, pending_);
  const double a = p_.distance_noise * m.moved_m;
  const double along = a * a;
  covariance(0, 0) += along;
  covariance(1, 1) += along;
  covariance(2, 2) += m.gyro_var + bias_var * (m.time_s * m.time_s);  // the biases' spread
  return covariance;
}

}  // namespace plantsim::robot
