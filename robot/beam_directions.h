// A scan's beams as unit directions in the world for a sensor heading: the sensor-frame table is
// made once per scan geometry and turned by the heading, one rotation per beam where a sine and
// a cosine per beam would cost several times more. Reused scan to scan by its owner (the lidar
// model, the EKF, perception).
#pragma once

#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "robot/readings.h"

namespace plantsim::robot {

class BeamDirections {
 public:
  std::span<const geom::Vec2> in_world(const LidarScan& scan, double sensor_yaw);

 private:
  double angle_min_ = 0, increment_ = 0;
  std::vector<geom::Vec2> sensor_frame_, world_;
};

}  // namespace plantsim::robot
