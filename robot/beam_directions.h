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
  /// Some beams of a scan turned by a heading, each on demand, bit for bit as in_world turns it:
  /// for a caller that needs a few beams (the EKF's matched faces) many times a scan.
  class Turned {
   public:
    geom::Vec2 operator[](std::size_t i) const {
      const geom::Vec2 u = frame_[i];
      return {c_ * u.x - s_ * u.y, s_ * u.x + c_ * u.y};
    }

   private:
    friend class BeamDirections;
    Turned(std::span<const geom::Vec2> frame, double c, double s) : frame_(frame), c_(c), s_(s) {}
    std::span<const geom::Vec2> frame_;
    double c_, s_;
  };

  std::span<const geom::Vec2> in_world(const LidarScan& scan, double sensor_yaw);
  Turned turned(const LidarScan& scan, double sensor_yaw);

 private:
  void fit_to(const LidarScan& scan);

  double angle_min_ = 0, increment_ = 0;
  std::vector<geom::Vec2> sensor_frame_, world_;
};

}  // namespace plantsim::robot
