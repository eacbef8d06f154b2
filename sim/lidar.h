// A 2D scanning lidar built from the physics' own shapes: the fan of beams cast exactly, in double
// precision, against the obstacles, walls, charger, moving obstacles and target the physics holds
// (PhysicsWorld::ray_fan: the static boxes in one pass over those within reach; Box2D's single-
// precision ray cast is only the reference tests compare with), with Gaussian range noise, random
// dropouts and no-return beams. All beams of a scan are cast at
// one instant (no motion distortion: at 0.6 m/s and 15 Hz a scan spans 4 cm of travel).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "robot/beam_directions.h"
#include "robot/readings.h"
#include "util/random_stream.h"
#include "worlds/surfaces.h"

namespace plantsim::sim {

class PhysicsWorld;

/// Defaults: a typical 2D safety lidar (270 degrees, 0.05-20 m, 15 Hz, 1 cm noise).
struct LidarParams {
  bool enabled = true;
  int beam_count = 360;                   ///< beams spread evenly over the field of view
  double field_of_view_rad = 1.5 * M_PI;  ///< total angle, centred on the mounting yaw
  double min_range_m = 0.05;              ///< closer surfaces give no return
  double max_range_m = 20.0;              ///< beyond: no return
  double rate_hz = 15.0;                  ///< scans per second
  double mount_x_m = 0.0;                 ///< mounting pose in the robot frame
  double mount_y_m = 0.0;
  double mount_yaw_rad = 0.0;
  double range_noise_m = 0.01;        ///< std-dev of each range
  double dropout_probability = 0.01;  ///< a beam returns nothing (dark or shiny surface)
  bool max_range_returns = true;      ///< no-return beams read max_range_m (else +inf)
};

class Lidar {
 public:
  Lidar(LidarParams params, std::uint64_t seed);
  /// True when a scan is due at time t (the first at t = 0).
  bool due(double t_s) const { return params_.enabled && t_s + 1e-9 >= next_scan_s_; }
  /// Scans from the robot's true pose (sensors see the real plant).
  robot::LidarScan scan(const PhysicsWorld& physics, const geom::Pose2& robot_truth, double t_s);
  const LidarParams& params() const { return params_; }

 private:
  LidarParams params_;
  util::RandomStream noise_;
  double next_scan_s_ = 0;
  robot::BeamDirections directions_;
  std::vector<double> hits_;  // the fan's ranges, reused scan to scan
};

}  // namespace plantsim::sim
