// A scan's returns as points in the robot's frame (the sensor's mounting applied): what the
// particle filter weighs, what a place is refined by and what the lost robot steers by.
#pragma once

#include <vector>

#include "geometry/vec2.h"
#include "robot/readings.h"

namespace plantsim::robot {

/// Up to `max_points` valid returns of `scan`, spread evenly over them (every k-th), in the
/// robot's frame; all of them when `max_points` is at least their number.
std::vector<geom::Vec2> scan_points(const LidarScan& scan, int max_points);

}  // namespace plantsim::robot
