// A scan's returns in the robot's frame (see scan_points.h).
#include "robot/scan_points.h"

#include <algorithm>

namespace plantsim::robot {

std::vector<geom::Vec2> scan_points(const LidarScan& scan, int max_points) {
  std::vector<std::size_t> valid;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i)
    if (scan.valid(i)) valid.push_back(i);
  std::vector<geom::Vec2> out;
  if (valid.empty() || max_points <= 0) return out;
  const std::size_t wanted = static_cast<std::size_t>(max_points);
  const std::size_t stride = std::max<std::size_t>(1, (valid.size() + wanted - 1) / wanted);
  for (std::size_t k = 0; k < valid.size(); k += stride) {
    const std::size_t i = valid[k];
    const geom::Vec2 in_sensor = scan.ranges[i] * geom::unit_from_angle(scan.angle(i));
    out.push_back(geom::compose(scan.mount, geom::Pose2{in_sensor.x, in_sensor.y, 0}).position());
  }
  return out;
}

}  // namespace plantsim::robot
