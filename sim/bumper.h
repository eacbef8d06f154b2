// The bumper: a switch strip around the body that closes when the robot touches an obstacle,
// a wall or a moving obstacle, reported as front (contact ahead of the axle) or rear. The
// charger's contact pads are not part of it.
#pragma once

#include <vector>

#include "geometry/vec2.h"
#include "robot/readings.h"

namespace plantsim::sim {

using robot::BumperReading;

/// From the contact points (world frame) and the robot's true pose.
BumperReading read_bumper(const std::vector<geom::Vec2>& contact_points,
                          const geom::Pose2& robot_truth);

}  // namespace plantsim::sim
