// The speed the robot can stop from within the free range it sees ahead: the largest v with
//   v * t_react + v^2 / (2 a) <= max(0, d_free - margin),
// that is v = -a t_react + sqrt((a t_react)^2 + 2 a max(0, d_free - margin)). What counts as
// free (the lidar's returns in the footprint's swept corridor) is the robot side's
// (robot/free_range.h); what deceleration the floor allows is the traction governor's learnt
// grip (controller/traction.h). Pure: no sensors, no physics.
#pragma once

namespace plantsim::controller {

/// The largest speed (m/s) from which braking at `decel_mps2`, after `reaction_s` at that speed,
/// ends before `free_m - margin_m`. 0 when the free range is within the margin; +inf when
/// `free_m` is +inf (nothing seen ahead to stop for: the bound does not apply).
double stopping_speed_mps(double free_m, double decel_mps2, double reaction_s, double margin_m);

/// The distance (m) that speed `v_mps` needs to stop: reaction, then braking at `decel_mps2`.
double stopping_distance_m(double v_mps, double decel_mps2, double reaction_s);

}  // namespace plantsim::controller
