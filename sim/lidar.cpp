// Beams, noise, dropouts.
#include "sim/lidar.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/physics_world.h"

namespace plantsim::sim {

Lidar::Lidar(LidarParams params, std::uint64_t seed)
    : params_(params), noise_(seed ^ 0x6c1d4a7e3b2f9085ULL) {}

robot::LidarScan Lidar::scan(const PhysicsWorld& physics, const geom::Pose2& robot_truth,
                             double t_s) {
  next_scan_s_ = t_s + 1.0 / params_.rate_hz;
  robot::LidarScan s;
  s.t_s = t_s;
  s.mount = {params_.mount_x_m, params_.mount_y_m, params_.mount_yaw_rad};
  const int n = params_.beam_count;
  s.angle_increment_rad = n > 1 ? params_.field_of_view_rad / (n - 1) : 0.0;
  s.angle_min_rad = n > 1 ? -0.5 * params_.field_of_view_rad : 0.0;  // sensor frame
  s.min_range_m = params_.min_range_m;
  s.max_range_m = params_.max_range_m;
  s.ranges.resize(static_cast<std::size_t>(n));
  const geom::Pose2 sensor = geom::compose(robot_truth, s.mount);
  const double no_return =
      params_.max_range_returns ? params_.max_range_m : std::numeric_limits<double>::infinity();
  const std::span<const geom::Vec2> directions = directions_.in_world(s, sensor.yaw);
  physics.ray_fan(sensor.position(), directions, sensor.yaw + s.angle(0), s.angle_increment_rad,
                  params_.max_range_m, hits_);
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
    // Noise and dropout are drawn for every beam, hit or not, so that one beam's outcome
    // never shifts the random stream of the others (scans stay comparable across worlds).
    const double noise = params_.range_noise_m * noise_.gaussian();
    const bool dropped = noise_.uniform() < params_.dropout_probability;
    double r = no_return;
    if (const double hit = hits_[i]; hit >= params_.min_range_m && hit <= params_.max_range_m)
      r = std::clamp(hit + noise, params_.min_range_m, params_.max_range_m);
    if (dropped) r = std::numeric_limits<double>::quiet_NaN();
    s.ranges[i] = r;
  }
  return s;
}

}  // namespace plantsim::sim
