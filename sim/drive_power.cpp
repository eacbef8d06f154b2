// The drive's electrical power (see the header).
#include "sim/drive_power.h"

#include <algorithm>
#include <cmath>

namespace plantsim::sim {

double wheel_power_w(const DrivePowerSpec& spec, double rim_force_n, double rim_speed_mps) {
  const double mechanical = rim_force_n * rim_speed_mps;  // negative: the wheel is braked
  const double drawn = std::max(0.0, mechanical) / (spec.motor_efficiency * spec.driver_efficiency);
  const double current =
      std::fabs(rim_force_n) * spec.wheel_radius_m / spec.torque_constant_nm_per_a;
  return drawn + current * current * spec.winding_resistance_ohm;
}

double robot_power_w(const DrivePowerSpec& spec, double left_force_n, double left_speed_mps,
                     double right_force_n, double right_speed_mps) {
  return spec.idle_w + wheel_power_w(spec, left_force_n, left_speed_mps) +
         wheel_power_w(spec, right_force_n, right_speed_mps);
}

}  // namespace plantsim::sim
