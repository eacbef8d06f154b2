// How far the robot can drive straight ahead before its footprint meets what its lidar sees:
// the free range the stopping bound brakes within (controller/stopping_bound.h, applied by the
// traction governor). Only the scan and the robot's own spec: no map, no truth. Beyond the
// lidar's range nothing is seen, so nothing there counts as free.
#pragma once

#include "robot/readings.h"
#include "worlds/world.h"

namespace plantsim::robot {

/// The distance (m, >= 0) the footprint of `robot` sweeps straight forward from where `scan`
/// was taken before it touches a return of `scan`: for a disk of radius r, a return at (x, y) in
/// the robot frame (x ahead) with |y| < r stops it after x - sqrt(r^2 - y^2); for a rectangle,
/// a return with |y| < width/2 after x - length/2. At most the lidar's max range less the
/// footprint's front (nothing returns from further). Returns behind the axle (x <= 0) are
/// not ahead.
double free_range_ahead_m(const LidarScan& scan, const worlds::RobotSpec& robot);

}  // namespace plantsim::robot
