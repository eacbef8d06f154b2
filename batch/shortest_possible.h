// The shortest path the robot's centre could have driven in an episode: a true lower bound on
// its driven length, so that driven / shortest possible is never below 1 (issue 52: the planning
// optimum, on obstacles grown by the robot's radius plus a margin, was beaten by 102 of 140 demo
// episodes, which cut the margin at corners and joined the approach early).
#pragma once

#include <optional>
#include <vector>

#include "episode/episode_result.h"
#include "planner/planner.h"
#include "worlds/world.h"

namespace plantsim::batch {

/// The plant's boxes (mapped and not; not the charger, which only makes the bound looser) and
/// walls grown with square corners by (r - slop) / sqrt(2), r the largest disk inside the
/// footprint: a box grown so in the max norm lies within r - slop of the box, where the centre
/// of a robot that does not pass through it never is. Square corners keep the visibility graph
/// exact, so its shortest path bounds every path the centre can take.
planner::PlannerInput shortest_possible_input(const worlds::World& plant);

/// The sum of the shortest paths of the legs the robot drove on `bound` (a planner built on
/// shortest_possible_input): from `start` to the first carry, between carries (a kidnap lifts the
/// robot: no driving), from the last to `end`. Nothing when a leg has no path.
std::optional<double> shortest_possible_m(planner::Planner& bound, const geom::Pose2& start,
                                          const std::vector<episode::EpisodeResult::Carry>& carries,
                                          geom::Vec2 end);

}  // namespace plantsim::batch
