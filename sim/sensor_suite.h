// Everything the robot's sensors report at one control step, and the suite that reads them
// from the physics. This is the only place (with the metrics) where the simulator's truth is
// read; what leaves it is a reading a real robot would have. The oracle readings exist only in
// perception mode "oracle", the comparison mode that keeps the old idealised sensing.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "sim/bumper.h"
#include "sim/charger_detector.h"
#include "sim/imu.h"
#include "sim/lidar.h"
#include "sim/localization.h"
#include "sim/odometry.h"
#include "sim/physics_world.h"
#include "sim/wheel_drive.h"
#include "worlds/world.h"

namespace plantsim::sim {

/// The moving target's beacon (a UWB tag it carries): its centre relative to the robot.
struct BeaconParams {
  double position_noise_m = 0.05;  ///< std-dev per axis
};

/// What the simulator knows, handed over only in oracle mode.
struct OracleReadings {
  std::optional<geom::Pose2> pose_fix;  ///< the old localiser: true pose plus noise, every period
  geom::Pose2 truth;                    ///< to place the actors as a perfect tracker would
  std::vector<ActorState> actors;
  std::optional<ActorState> target;
};

struct SensorReadings {
  double t_s = 0;
  double dt_s = 0;                   ///< since the previous reading
  double encoder_distance_m = 0;     ///< wheel travel since the previous reading (odometry)
  geom::Pose2 odom_pose;             ///< dead-reckoned from the encoders alone
  double odom_speed_mps = 0;
  double gyro_yaw_rate_radps = 0;
  std::optional<LidarScan> scan;     ///< a new scan, when one was taken
  std::optional<ChargerDetection> charger;  ///< a detection whose latency has passed
  BumperReading bumper;
  bool charger_contact = false;      ///< the pads touch the charger (since the previous reading)
  bool charging = false;             ///< the charger's signal
  std::optional<geom::Vec2> target_in_robot;  ///< the beacon of a moving target
  std::optional<OracleReadings> oracle;
};

struct SensorParams {
  bool oracle = false;  ///< perception mode "oracle"
  LidarParams lidar;
  ImuParams imu;
  DetectionParams detection;
  OdometryNoise odometry;
  LocalizationParams oracle_fix;  ///< oracle mode's noisy truth fixes
  BeaconParams beacon;
  double charge_position_tolerance_m = 0.02;  ///< the charger's pads engage within these
  double charge_heading_tolerance_rad = 2.0 * M_PI / 180.0;
};

class SensorSuite {
 public:
  SensorSuite(const worlds::World& plant, const SensorParams& params, std::uint64_t seed);
  /// Counts one physics step of encoder travel and latches contacts (every step).
  void count(const PhysicsWorld& physics, const WheelDrive& drive, double dt_s);
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
  std::mt19937_64 rng_;
  std::normal_distribution<double> gauss_{0.0, 1.0};
  double last_read_s_ = 0;
  geom::Pose2 last_odom_;
  bool contact_ = false, charging_ = false;
  std::vector<geom::Vec2> contact_points_;
  geom::Vec2 charger_marker_;
};

}  // namespace plantsim::sim
