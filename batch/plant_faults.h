// Faults that change the plant, not the robot: a person crossing the planned path or the
// final approach, and obstacles the map lacks placed across the optimal path. Each is
// deterministic for its seed, and never makes the charger unreachable for a robot that
// senses what is there (unmapped boxes that would close every way are shrunk or left out).
#pragma once

#include <cstdint>
#include <vector>

#include "worlds/world.h"

namespace plantsim::batch {

/// A person crossing the planned path at its middle, timed to meet the robot there.
worlds::MovingObstacle crossing_person(const worlds::World& w, const std::vector<geom::Vec2>& plan);

/// A blind person crossing the final approach halfway between the staging pose and the
/// charger, once, timed to arrive there as a robot driving the plan at a steady pace would.
worlds::MovingObstacle final_approach_crosser(const worlds::World& w, double plan_length_m);

/// A person standing on the final approach, halfway between the staging pose and the charger,
/// from the start until `standing_s` after a robot driving the plan at a steady pace would
/// reach the staging pose; then they walk off to the side with more room.
worlds::MovingObstacle person_standing_at_dock(const worlds::World& w, double plan_length_m,
                                               double standing_s);

/// `count` boxes the map lacks, spread along the optimal `plan` (start to staging pose), each
/// 0.4-0.9 m a side and straddling the path, away from the start and the final approach.
/// A box is shrunk, then dropped, when the plant would no longer leave a way to the charger
/// at the clearance the robot's replanning keeps (`replan_clearance_m` beyond its inflation).
std::vector<geom::Rect> unmapped_across_path(const worlds::World& w,
                                             const std::vector<geom::Vec2>& plan, int count,
                                             std::uint64_t seed, double replan_clearance_m = 0.1);

}  // namespace plantsim::batch
