// Pose composition and the periodic noisy fix.
#include "sim/localization.h"

namespace plantsim::sim {

Localization::Localization(LocalizationParams params, std::uint64_t seed)
    : params_(params), noise_(seed ^ 0x5bd1e995u) {}

void Localization::update(double t_s, const geom::Pose2& odom, const geom::Pose2& truth) {
  if (params_.period_s <= 0 || t_s < next_fix_s_) return;
  next_fix_s_ = t_s + params_.period_s;
  const geom::Pose2 fix{truth.x + params_.position_noise_m * noise_.gaussian(),
                        truth.y + params_.position_noise_m * noise_.gaussian(),
                        geom::wrap_angle(truth.yaw + params_.yaw_noise_rad * noise_.gaussian())};
  map_from_odom_ = geom::compose(fix, geom::inverse(odom));
  fixed_ = true;
}

}  // namespace plantsim::sim
