// Where the dock is, in the odometry frame (which never jumps): placed once from the map at the
// staging pose, then pulled towards every charger detection (Nav2's docking keeps such a pose
// filter apart). A detection far from the estimate is an outlier unless the next one confirms it,
// so a map placement that was off is corrected by two agreeing detections.
#pragma once

#include <optional>

#include "controller/path_geometry.h"

namespace plantsim::controller {

struct DockPoseFilterParams {
  double detection_blend = 0.3;   ///< weight of each new detection in the dock estimate
  double detection_gate_m = 0.1;  ///< a detection further than this from the dock estimate is
                                  ///< used only when the one before it agrees (outliers are single)
};

class DockPoseFilter {
 public:
  /// `staging_distance_m` turns the gate into an angle (the gate's offset seen from staging).
  DockPoseFilter(DockPoseFilterParams params, double staging_distance_m, const Pose2& initial);

  /// The dock placed (from the map, at the staging pose): detections count from now on.
  void place(const Pose2& dock_in_odom);
  /// The estimate is stale (the robot was shoved: the odometry never saw it): not placed, and
  /// the detection held back forgotten.
  void forget();
  bool placed() const { return placed_; }
  /// A detection of the docked pose in the odometry frame; ignored until placed.
  void update(const Pose2& seen);
  const Pose2& pose() const { return dock_; }

 private:
  bool near(const Pose2& a, const Pose2& b) const;

  DockPoseFilterParams params_;
  double staging_distance_m_;
  Pose2 dock_;
  bool placed_ = false;
  std::optional<Pose2> rejected_;  // the last detection the gate held back
};

}  // namespace plantsim::controller
