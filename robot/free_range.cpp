// The footprint's corridor ahead, cut by the scan's returns.
#include "robot/free_range.h"

#include <algorithm>
#include <cmath>

#include "geometry/vec2.h"

namespace plantsim::robot {

double free_range_ahead_m(const LidarScan& scan, const worlds::RobotSpec& robot) {
  const double half_width = robot.rectangular() ? 0.5 * robot.width_m : robot.radius_m;
  double free = std::max(0.0, scan.max_range_m - robot.front_extent_m());
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (!scan.valid(i)) continue;
    const double a = scan.angle(i), r = scan.ranges[i];
    const geom::Vec2 p =
        geom::compose(scan.mount, geom::Pose2{r * std::cos(a), r * std::sin(a), 0}).position();
    if (p.x <= 0 || std::fabs(p.y) >= half_width) continue;
    const double reach =
        robot.rectangular() ? 0.5 * robot.length_m : std::sqrt(half_width * half_width - p.y * p.y);
    free = std::min(free, std::max(0.0, p.x - reach));
  }
  return free;
}

}  // namespace plantsim::robot
