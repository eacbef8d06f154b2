// The oscillation critic's bookkeeping (see the header).
#include "controller/dwb/oscillation.h"

#include <cmath>

namespace plantsim::controller::dwb {

bool OscillationCritic::Trend::update(double v) {
  bool flipped_now = false;
  if (v < 0) {
    if (sign > 0) negative_only = flipped_now = true;
    sign = -1;
  } else if (v > 0) {
    if (sign < 0) positive_only = flipped_now = true;
    sign = 1;
  }
  return flipped_now;
}

void OscillationCritic::sent(const Twist& command, const geom::Pose2& pose) {
  bool flipped_now = x_.update(command.v_mps);
  if (std::fabs(command.v_mps) <= p_.x_only_threshold)
    flipped_now = theta_.update(command.omega_radps) || flipped_now;
  if (flipped_now) flipped_at_ = pose;
  if (!x_.flipped() && !theta_.flipped()) return;
  const double moved = geom::distance(pose.position(), flipped_at_.position());
  const double turned = std::fabs(std::remainder(pose.yaw - flipped_at_.yaw, 2.0 * M_PI));
  if (moved > p_.reset_dist_m || turned > p_.reset_angle_rad) reset();
}

}  // namespace plantsim::controller::dwb
