// The electrical power the drive and the robot's electronics draw (issue 91, first slice): each
// wheel's motor turns its rim force and speed (as the physics gives them) into mechanical power,
// drawn through the motor's and its driver's efficiencies, plus the copper loss of the current
// its torque needs (a stalled motor pushing a wall heats and drains, and moves nothing); braking
// regenerates nothing (a small robot's drivers seldom do). An idle load (computer, sensors)
// draws all the time.
#pragma once

namespace plantsim::sim {

struct DrivePowerSpec {
  double motor_efficiency = 0.85;
  double driver_efficiency = 0.95;
  double wheel_radius_m = 0.1;
  double torque_constant_nm_per_a = 0.8;  ///< at the wheel, through the gearbox
  double winding_resistance_ohm = 0.5;
  double idle_w = 30.0;  ///< computer, lidar, camera, radio
};

/// Electrical power (W) of one wheel's motor pushing with `rim_force_n` at `rim_speed_mps`.
double wheel_power_w(const DrivePowerSpec& spec, double rim_force_n, double rim_speed_mps);

/// The whole robot's: both wheels and the idle load.
double robot_power_w(const DrivePowerSpec& spec, double left_force_n, double left_speed_mps,
                     double right_force_n, double right_speed_mps);

}  // namespace plantsim::sim
