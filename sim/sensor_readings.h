// Everything the robot's sensors report at one control step: what perception may build on.
// The oracle readings exist only in perception mode "oracle", the comparison mode that keeps
// the old idealised sensing; they are the one place the simulator's knowledge is handed over,
// and they are named as such.
#pragma once

#include <optional>
#include <vector>

#include "sim/actor_state.h"
#include "sim/bumper.h"
#include "sim/charger_detector.h"
#include "sim/lidar.h"

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

}  // namespace plantsim::sim
