// The navigation-benchmark metrics from the truth (see the header).
#include "episode/navigation_metrics.h"

#include <algorithm>
#include <cmath>

namespace plantsim::episode {

NavigationMetrics::NavigationMetrics(const worlds::World& plant, double control_period_s)
    : clearance_(plant), period_s_(control_period_s) {}

void NavigationMetrics::sample(const geom::Pose2& truth, double speed_mps, double yaw_rate_radps,
                               const std::vector<geom::Rect>& moving, bool travelling) {
  if (!travelling) {
    chain_ = 0;
    return;
  }
  const double c = clearance_.at(truth, moving);
  min_clearance_ = samples_ == 0 ? c : std::min(min_clearance_, c);
  clearance_sum_ += c;
  near_ += c < kNearObstacle_m;
  ++samples_;
  // Differences over consecutive control periods only: acceleration needs two samples, jerk three.
  if (chain_ >= 1) {
    const double accel = (speed_mps - speed_) / period_s_;
    const double angular = (yaw_rate_radps - yaw_rate_) / period_s_;
    angular_sq_ += angular * angular, ++angular_;
    if (chain_ >= 2) {
      const double jerk = (accel - accel_) / period_s_;
      jerk_sq_ += jerk * jerk, ++jerks_;
    }
    accel_ = accel;
  }
  speed_ = speed_mps, yaw_rate_ = yaw_rate_radps;
  chain_ = std::min(chain_ + 1, 2);
}

void NavigationMetrics::write(EpisodeOutcome& r) const {
  if (samples_ > 0) {
    r.min_clearance_m = min_clearance_;
    r.mean_clearance_m = clearance_sum_ / static_cast<double>(samples_);
    r.near_obstacle_share = static_cast<double>(near_) / static_cast<double>(samples_);
  }
  if (jerks_ > 0) r.rms_jerk_mps3 = std::sqrt(jerk_sq_ / static_cast<double>(jerks_));
  if (angular_ > 0)
    r.rms_angular_accel_radps2 = std::sqrt(angular_sq_ / static_cast<double>(angular_));
}

}  // namespace plantsim::episode
