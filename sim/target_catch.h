// The referee's rule that ends a pursuit (seed 001's moving target): the target is caught when
// the robot's disk comes within the catch distance of its box, edge to edge, on the truth.
#pragma once

#include "sim/physics_world.h"

namespace plantsim::sim {

/// True when the moving target is within `catch_distance_m` of the robot's disk of
/// `robot_radius_m` (false when the plant has no target).
bool target_caught(const PhysicsWorld& physics, double robot_radius_m, double catch_distance_m);

}  // namespace plantsim::sim
