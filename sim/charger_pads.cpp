// Pad compression, tolerance and dwell.
#include "sim/charger_pads.h"

#include <cmath>

namespace plantsim::sim {

void ChargerPads::step(const geom::Pose2& robot, const geom::Pose2& docked, double dt_s) {
  // The robot's centre in the docked pose's frame: x along the approach, 0 at the docked pose.
  const geom::Vec2 rel = geom::rotate(robot.position() - docked.position(), -docked.yaw);
  const double compression = rel.x + 0.5 * p_.travel_m;
  const double heading_error = std::fabs(geom::wrap_angle(robot.yaw - docked.yaw));
  touched_ = compression > 0 && compression <= p_.travel_m + p_.max_overtravel_m &&
             std::fabs(rel.y) <= 0.5 * p_.contact_width_m && heading_error < 0.5;
  const bool good = touched_ && compression >= p_.min_press_m &&
                    std::fabs(rel.y) <= p_.lateral_tolerance_m &&
                    heading_error <= p_.heading_tolerance_rad;
  pressed_for_s_ = good ? pressed_for_s_ + dt_s : 0.0;
  charging_ = good && pressed_for_s_ + 1e-9 >= p_.dwell_s;
}

}  // namespace plantsim::sim
