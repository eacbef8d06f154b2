// The work one episode may ask for, judged before it starts: the physics steps its timeout
// allows times the bodies that move in each (the robot and every scripted mover). Each input in
// range can still ask for too much together: 83,000 s with 1,000 movers took 80 minutes.
#pragma once

#include "episode/episode_config.h"
#include "worlds/world.h"

namespace plantsim::episode {

/// Mover-steps an episode may ask for: a mover costs about 0.7 us a step here (1,000 movers
/// over 3,600 steps took 2.5 s), so this is about six minutes of computing at most.
inline constexpr double kMaxEpisodeMoverSteps = 5e8;

/// Throws std::invalid_argument naming the world and the config's timeout when `plant`'s movers
/// over `config`'s steps exceed kMaxEpisodeMoverSteps, saying how long it would take; and when a
/// travel speed exceeds the robot's motors (robot_limits.h).
void check_episode_work(const worlds::World& plant, const EpisodeConfig& config);

}  // namespace plantsim::episode
