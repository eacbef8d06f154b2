// The navigation-benchmark metrics (MRPB's, BARN's): over the travel to the staging pose (the
// control periods whose decision is in the travel phase, the local controller's stretch, not the
// docking that follows it, which is the same whichever controller drives), the true footprint's
// minimum and mean clearance to the true obstacles, the share of that time within
// kNearObstacle_m of one, and the smoothness of the true motion sampled at the control period:
// RMS jerk (the forward speed's second difference) and RMS angular acceleration (the yaw rate's
// first difference). Measured from the truth for the referee only: nothing here feeds back.
#pragma once

#include <cstdint>
#include <vector>

#include "episode/episode_result.h"
#include "episode/footprint_clearance.h"

namespace plantsim::episode {

/// Closer than this to an obstacle, a wall or a person counts as near (MRPB's safety distance).
inline constexpr double kNearObstacle_m = 0.3;

class NavigationMetrics {
 public:
  NavigationMetrics(const worlds::World& plant, double control_period_s);
  /// One control period's true state: pose, forward speed, yaw rate, the moving obstacles' boxes;
  /// `travelling` false outside the travel phase (that period is left out, and breaks the chain
  /// of differences).
  void sample(const geom::Pose2& truth, double speed_mps, double yaw_rate_radps,
              const std::vector<geom::Rect>& moving, bool travelling);
  /// The robot was carried off (a kidnap): no difference spans the carry.
  void carried() { chain_ = 0; }
  /// The metrics into the outcome (NaN where nothing was measured).
  void write(EpisodeOutcome& r) const;

 private:
  FootprintClearance clearance_;
  double period_s_;
  std::int64_t samples_ = 0, near_ = 0;
  double min_clearance_ = 0, clearance_sum_ = 0;
  int chain_ = 0;  // consecutive travel samples behind the current one (at most 2 matter)
  double speed_ = 0, accel_ = 0, yaw_rate_ = 0;  // at the last travel sample
  std::int64_t jerks_ = 0, angular_ = 0;
  double jerk_sq_ = 0, angular_sq_ = 0;
};

}  // namespace plantsim::episode
