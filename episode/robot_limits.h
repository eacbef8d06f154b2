// Parameters the robot's own hardware bounds: a travel speed above the motors' limit (the world's
// robot.max_speed_mps, the rim speed) is a setting the robot cannot drive, so it is refused
// before any work, in configurations, sweeps and tuning bounds alike (a tuning once "found" 1.47
// m/s for a robot whose motors give 0.8 m/s). Only the chosen local controller's speed counts.
#pragma once

#include <string>
#include <vector>

#include "episode/episode_config.h"
#include "worlds/world.h"

namespace plantsim::episode {

/// The speed parameters the motors bound, for the travel `config` chooses: the local
/// controller's cruise (tracking.max_linear_speed_mps, mppi.vx_max, dwb.max_vel_x) or the
/// potential field's (potential_field.max_speed_mps).
std::vector<std::string> motor_bounded_parameters(const EpisodeConfig& config);

/// Throws std::invalid_argument naming the key, its value, the limit and the world when one of
/// those parameters, set to other than its default, exceeds `plant`'s robot.max_speed_mps (a
/// default above a slow robot's limit is capped by the drive, not refused).
void check_robot_limits(const worlds::World& plant, const EpisodeConfig& config);

/// The same for a tuning bound: `path` tuned up to `hi` on `plant`.
void check_tuning_bound(const worlds::World& plant, const EpisodeConfig& config,
                        const std::string& path, double hi);

}  // namespace plantsim::episode
