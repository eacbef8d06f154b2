// The suite that reads every sensor from the physics at each control step: the registered
// sensor models (sim/sensor_model.h) in their order. With the metrics, this is the only place
// where the simulator's truth is read; what leaves it is a reading a real robot would have
// (robot/readings.h).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "robot/readings.h"
#include "sim/sensor_model.h"

namespace plantsim::sim {

using robot::OracleReadings;
using robot::SensorReadings;

class SensorSuite {
 public:
  SensorSuite(const worlds::World& plant, const SensorParams& params, std::uint64_t seed);
  /// The robot was put elsewhere by a fault (a kidnap is a teleport, no motion): the gyro felt
  /// none.
  void robot_placed(const geom::Pose2& pose);
  /// Counts one physics step of encoder travel and latches the contacts it left (every step).
  void count(const PhysicsWorld& physics, const ContactState& contact, const WheelDrive& drive,
             double dt_s);
  /// Reads every sensor at the control step at time t.
  SensorReadings read(const PhysicsWorld& physics, double t_s);

 private:
  SensorParams p_;
  std::vector<std::unique_ptr<SensorModel>> models_;
  double last_read_s_ = 0;
};

}  // namespace plantsim::sim
