// What the robot's sensors report, the only way the plant reaches the robot's side: a lidar
// scan, the wheel encoders' odometry, the gyro, the bumper, charger detections, the charger's
// signal and a moving target's beacon. The simulator's sensor models (sim/) fill these in from
// the physics; nothing on the robot's side sees more. The oracle readings exist only in
// perception mode "oracle", the comparison mode that keeps the old idealised sensing: they are
// the one place the simulator's knowledge is handed over, and they are named as such.
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::robot {

/// One scan in the sensor frame. ranges[i] is along angle_min + i * angle_increment (sensor
/// frame); a dropout is NaN; a beam with no surface within range reads max_range_m (or +inf).
struct LidarScan {
  double t_s = 0;
  geom::Pose2 mount;  ///< sensor in the robot frame
  double angle_min_rad = 0;
  double angle_increment_rad = 0;
  double min_range_m = 0, max_range_m = 0;
  std::vector<double> ranges;

  double angle(std::size_t i) const {
    return angle_min_rad + static_cast<double>(i) * angle_increment_rad;
  }
  /// A real return: finite, within [min, max) (a max-range reading is no surface).
  bool valid(std::size_t i) const {
    return std::isfinite(ranges[i]) && ranges[i] >= min_range_m && ranges[i] < max_range_m;
  }
};

/// A charger detection: the docked pose in the robot frame at the time the image was taken.
struct ChargerDetection {
  double captured_s;
  geom::Pose2 dock_in_robot;
};

/// The bumper strip: front (contact ahead of the axle) or rear.
struct BumperReading {
  bool front = false;
  bool rear = false;
  bool pressed() const { return front || rear; }
};

/// A scripted obstacle (or the moving target) as it is at one instant: its box and velocity.
struct ActorState {
  geom::Rect box;
  geom::Vec2 velocity;  ///< world frame
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
  double dt_s = 0;                ///< since the previous reading
  double encoder_distance_m = 0;  ///< wheel travel since the previous reading (odometry)
  geom::Pose2 odom_pose;          ///< dead-reckoned from the encoders alone
  double odom_speed_mps = 0;
  double gyro_yaw_rate_radps = 0;
  std::optional<LidarScan> scan;            ///< a new scan, when one was taken
  std::optional<ChargerDetection> charger;  ///< a detection whose latency has passed
  BumperReading bumper;
  bool charger_contact = false;  ///< the pads touch the charger (since the previous reading)
  bool charging = false;         ///< the charger's signal
  std::optional<geom::Vec2> target_in_robot;  ///< the beacon of a moving target
  std::optional<OracleReadings> oracle;
};

}  // namespace plantsim::robot
