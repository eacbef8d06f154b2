// The EKF as the robot's pose estimator (`localization.estimator: ekf`, the default): the
// filter (ekf_localizer.h) updated locally by each scan while its spread is small, and found
// again by a global scan match (scan_matcher.h) in a window of three sigmas when it is wide: an
// unambiguous match the beams confirm restarts it, an ambiguous one that fits updates it along
// what it pins down.
#pragma once

#include <optional>

#include "robot/ekf_localizer.h"
#include "robot/global_match.h"
#include "robot/pose_estimator.h"
#include "robot/scan_matcher.h"

namespace plantsim::robot {

/// The covariance a confirmed global match restarts the filter with: the match's `spread` (the
/// poses that fit about as well, ScanMatch::spread) with its position's principal sigmas held
/// between the grid's cell and `max_sigma_m`, its heading's at least `min_yaw_sigma_rad`.
Eigen::Matrix3d reset_covariance(const Eigen::Matrix3d& spread, double cell_m, double max_sigma_m,
                                 double min_yaw_sigma_rad);

class EkfEstimator final : public PoseEstimator {
 public:
  EkfEstimator(const worlds::World& map, const MapRaycaster& raycaster, const EkfParams& ekf,
               const GlobalMatchParams& global);

  void predict(double distance_m, double gyro_yaw_rate_radps, double dt_s) override {
    ekf_.predict(distance_m, gyro_yaw_rate_radps, dt_s);
  }
  void standstill(double gyro_yaw_rate_radps, double dt_s) override {
    ekf_.standstill(gyro_yaw_rate_radps, dt_s);
  }
  void observe(const LidarScan& scan) override;
  void widen(double position_sigma_m, double yaw_sigma_rad) override {
    ekf_.widen(position_sigma_m, yaw_sigma_rad);
  }
  geom::Pose2 pose() const override { return ekf_.pose(); }
  Eigen::Matrix3d pose_covariance() const override { return ekf_.pose_covariance(); }
  double position_sigma_m() const override { return ekf_.position_sigma_m(); }
  double yaw_sigma_rad() const override { return ekf_.yaw_sigma_rad(); }
  double gyro_bias_radps() const override { return ekf_.gyro_bias_radps(); }
  double range_sigma_m() const override { return ekf_.range_sigma_m(); }
  LocalizationHealth health() const override { return ekf_.health(); }
  int failed_matches() const override { return ekf_.failed_matches(); }
  bool lost_in_view() const override {
    return ekf_.health() == LocalizationHealth::kLost && unmatched_;
  }
  int relocalizations() const override { return relocalizations_; }
  const EkfLocalizer& filter() const { return ekf_; }

 private:
  /// Wide estimate: match the scan globally; true when the filter may also update locally.
  bool relocalize(const LidarScan& scan);
  /// A confirmed, unambiguous match: fused when the estimate holds it, else a restart there.
  void place(const ScanMatch& m);
  /// After an ambiguous match's update: the estimate kept wide enough that the next window
  /// still holds the places the scan fitted about as well.
  void keep_look_alikes_in_window(const ScanMatch& m);

  const worlds::World& map_;
  const MapRaycaster& raycaster_;
  GlobalMatchParams p_;
  double lost_sigma_m_;  // EkfParams::lost_position_sigma_m
  EkfLocalizer ekf_;
  std::optional<ScanMatcher> matcher_;  // built the first time it is needed
  double next_match_s_ = 0;
  int relocalizations_ = 0;
  bool unmatched_ = false;  // lost, and the last scan with enough returns matched nowhere
};

}  // namespace plantsim::robot
