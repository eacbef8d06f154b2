// The catch rule, on the physics' truth.
#include "sim/target_catch.h"

#include <optional>

#include "controller/collision_check.h"

namespace plantsim::sim {

bool target_caught(const PhysicsWorld& physics, double robot_radius_m, double catch_distance_m) {
  const std::optional<robot::ActorState> target = physics.target();
  return target &&
         controller::distance_to_box(physics.robot_position(), target->box) - robot_radius_m <=
             catch_distance_m;
}

}  // namespace plantsim::sim
