// The dock's pose filter: an exponential blend of detections behind a two-in-a-row gate.
#include "controller/dock_pose_filter.h"

#include <cmath>

namespace plantsim::controller {

DockPoseFilter::DockPoseFilter(DockPoseFilterParams params, double staging_distance_m,
                               const Pose2& initial)
    : params_(params), staging_distance_m_(staging_distance_m), dock_(initial) {}

void DockPoseFilter::place(const Pose2& dock_in_odom) {
  dock_ = dock_in_odom;
  placed_ = true;
}

void DockPoseFilter::forget() {
  placed_ = false;
  rejected_.reset();
}

bool DockPoseFilter::near(const Pose2& a, const Pose2& b) const {
  return geom::distance(a.position(), b.position()) <= params_.detection_gate_m &&
         std::fabs(geom::wrap_angle(a.yaw - b.yaw)) <=
             params_.detection_gate_m / staging_distance_m_;
}

void DockPoseFilter::update(const Pose2& seen) {
  if (!placed_) return;
  if (!near(seen, dock_)) {
    const bool confirmed = rejected_ && near(seen, *rejected_);
    rejected_ = seen;
    if (!confirmed) return;
  }
  rejected_.reset();
  const double a = params_.detection_blend;
  dock_.x += a * (seen.x - dock_.x);
  dock_.y += a * (seen.y - dock_.y);
  dock_.yaw = geom::wrap_angle(dock_.yaw + a * geom::wrap_angle(seen.yaw - dock_.yaw));
}

}  // namespace plantsim::controller
