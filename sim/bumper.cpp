// Contact points into the robot frame.
#include "sim/bumper.h"

namespace plantsim::sim {

using robot::BumperReading;

BumperReading read_bumper(const std::vector<geom::Vec2>& contact_points,
                          const geom::Pose2& robot_truth) {
  BumperReading b;
  for (const geom::Vec2& p : contact_points) {
    const double ahead = geom::dot(p - robot_truth.position(), robot_truth.heading());
    if (ahead >= 0)
      b.front = true;
    else
      b.rear = true;
  }
  return b;
}

}  // namespace plantsim::sim
