// Perception mode "oracle" only (the comparison mode): where the robot believes it is, from
// continuous wheel odometry (which drifts) and, optionally, periodic fixes that are the true
// pose plus noise, standing in for a scan-matching or AMCL-like localiser. Sensors mode
// localises with the EKF (ekf_localizer.h) instead. The fixes move the map-from-odometry transform,
// as in ROS (map -> odom -> base_link), so the odometry frame itself never jumps: docking works in
// it.
#pragma once

#include "geometry/vec2.h"
#include "util/random_stream.h"

namespace plantsim::sim {

struct LocalizationParams {
  double period_s = 0.0;          ///< seconds between fixes; 0 = no fixes (odometry only)
  double position_noise_m = 0.0;  ///< std-dev per axis of each fix
  double yaw_noise_rad = 0.0;     ///< std-dev of each fix's heading
};

class Localization {
 public:
  Localization(LocalizationParams params, std::uint64_t seed);
  /// Called every step with the time, the odometry pose and the ground truth (for the fix).
  void update(double t_s, const geom::Pose2& odom, const geom::Pose2& truth);
  geom::Pose2 map_pose(const geom::Pose2& odom) const {
    return fixed_ ? geom::compose(map_from_odom_, odom) : odom;  // identity until the first fix
  }
  const geom::Pose2& map_from_odom() const { return map_from_odom_; }

 private:
  LocalizationParams params_;
  util::RandomStream noise_;
  geom::Pose2 map_from_odom_;
  double next_fix_s_ = 0.0;
  bool fixed_ = false;
};

}  // namespace plantsim::sim
