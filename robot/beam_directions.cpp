// The sensor-frame table and its rotation.
#include "robot/beam_directions.h"

#include <cmath>

namespace plantsim::robot {

void BeamDirections::fit_to(const LidarScan& scan) {
  const std::size_t n = scan.ranges.size();
  if (sensor_frame_.size() != n || angle_min_ != scan.angle_min_rad ||
      increment_ != scan.angle_increment_rad) {
    sensor_frame_.resize(n);
    for (std::size_t i = 0; i < n; ++i) sensor_frame_[i] = geom::unit_from_angle(scan.angle(i));
    angle_min_ = scan.angle_min_rad, increment_ = scan.angle_increment_rad;
  }
}

BeamDirections::Turned BeamDirections::turned(const LidarScan& scan, double sensor_yaw) {
  fit_to(scan);
  return Turned(sensor_frame_, std::cos(sensor_yaw), std::sin(sensor_yaw));
}

std::span<const geom::Vec2> BeamDirections::in_world(const LidarScan& scan, double sensor_yaw) {
  fit_to(scan);
  const std::size_t n = scan.ranges.size();
  world_.resize(n);
  const double c = std::cos(sensor_yaw), s = std::sin(sensor_yaw);
  for (std::size_t i = 0; i < n; ++i) {
    const geom::Vec2 u = sensor_frame_[i];
    world_[i] = {c * u.x - s * u.y, s * u.x + c * u.y};
  }
  return world_;
}

}  // namespace plantsim::robot
