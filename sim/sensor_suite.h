// The suite that reads every sensor from the physics at each control step. With the metrics,
// this is the only place where the simulator's truth is read; what leaves it is a reading a
// real robot would have (robot/readings.h).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "robot/readings.h"
#include "sim/bumper.h"
#include "sim/charger_detector.h"
#include "sim/charger_pads.h"
#include "sim/imu.h"
#include "sim/lidar.h"
#include "sim/localization.h"
#include "sim/odometry.h"
#include "sim/physics_world.h"
#include "sim/wheel_drive.h"
#include "util/random_stream.h"
#include "worlds/world.h"

namespace plantsim::sim {

using robot::OracleReadings;
using robot::SensorReadings;

/// The moving target's beacon (a UWB tag it carries): its centre relative to the robot.
struct BeaconParams {
  double position_noise_m = 0.05;  ///< std-dev per axis
};

struct SensorParams {
  bool oracle = false;  ///< perception mode "oracle"
  LidarParams lidar;
  ImuParams imu;
  DetectionParams detection;
  OdometryNoise odometry;
  LocalizationParams oracle_fix;  ///< oracle mode's noisy truth fixes
  BeaconParams beacon;
  ChargerPadParams pads;  ///< travel set from the plant's charger
};

class SensorSuite {
 public:
  SensorSuite(const worlds::World& plant, const SensorParams& params, std::uint64_t seed);
  /// The robot was put elsewhere by a fault (a kidnap is a teleport, no motion): the gyro felt
  /// none.
  void robot_placed(const geom::Pose2& pose) { last_yaw_ = pose.yaw; }
  /// Counts one physics step of encoder travel and latches the contacts it left (every step).
  void count(const PhysicsWorld& physics, const ContactState& contact, const WheelDrive& drive,
             double dt_s);
  /// Reads every sensor at the control step at time t.
  SensorReadings read(const PhysicsWorld& physics, double t_s);

 private:
  const worlds::World& plant_;
  SensorParams p_;
  Odometry odometry_;
  Imu imu_;
  Lidar lidar_;
  ChargerDetector detector_;
  Localization oracle_fix_;
  ChargerPads pads_;
  util::RandomStream noise_;
  double last_read_s_ = 0;
  geom::Pose2 last_odom_;
  double last_yaw_ = 0;  // the body's true heading at the last reading, for the gyro's increment
  bool contact_ = false, charging_ = false;
  std::vector<geom::Vec2> contact_points_;
  geom::Vec2 charger_marker_;
};

}  // namespace plantsim::sim
