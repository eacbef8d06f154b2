// Charger detection as a camera reading a marker on the charger's face (or a lidar matching
// its shape) would give it: the docked pose in the robot frame, seen only within range and
// field of view and when the line of sight from the sensor to the marker reaches the charger
// before anything else; with noise, false negatives, outliers, and a latency after which each
// detection is delivered (stamped with the time its image was taken).
#pragma once

#include <cstdint>
#include <deque>
#include <optional>

#include "geometry/vec2.h"
#include "robot/readings.h"
#include "util/random_stream.h"

namespace plantsim::sim {

class PhysicsWorld;

struct DetectionParams {
  bool enabled = true;
  double range_m = 2.0;             ///< charger visible within this distance
  double field_of_view_rad = 1.2;   ///< total angle, centred on the robot's heading
  double rate_hz = 10.0;            ///< images per second
  double mount_x_m = 0.0;           ///< camera position in the robot frame, looking ahead
  double position_noise_m = 0.003;  ///< std-dev per axis of each detection
  double yaw_noise_rad = 0.003;
  double false_negative_probability = 0.05;  ///< a visible marker is missed
  double outlier_probability = 0.01;  ///< a detection is grossly wrong (reflection, wrong match)
  double outlier_position_m = 0.3;    ///< std-dev of an outlier's position error
  double outlier_yaw_rad = 0.3;       ///< ... and heading error
  double latency_s = 0.1;             ///< from image to detection
  bool occlusion = true;              ///< the line of sight must be free (oracle mode: off)
};

using robot::ChargerDetection;

class ChargerDetector {
 public:
  ChargerDetector(DetectionParams params, std::uint64_t seed);
  /// Takes an image when one is due (from the robot's true pose and the charger's real pose)
  /// and returns the detection whose latency has passed, if any.
  std::optional<ChargerDetection> update(const PhysicsWorld& physics,
                                         const geom::Pose2& robot_truth,
                                         const geom::Pose2& dock_truth, geom::Vec2 marker,
                                         double t_s);

 private:
  std::optional<geom::Pose2> observe(const PhysicsWorld& physics, const geom::Pose2& robot_truth,
                                     const geom::Pose2& dock_truth, geom::Vec2 marker);
  DetectionParams p_;
  util::RandomStream noise_;
  double next_image_s_ = 0;
  std::deque<ChargerDetection> pending_;
};

}  // namespace plantsim::sim
