// One docking episode: plan to the staging pose, then the closed loop of sensing (the sensor
// suite), perception (EKF and tracker, or the oracle), the travel mode, the wheel drive and a
// fixed Box2D step, until docked, failed or timed out. Returns the metrics (from the truth, kept
// apart in episode_metrics.h) and the full trajectory log (episode_result.h).
// Deterministic: the same world, planner, config and seed give the same trajectory.
#pragma once

#include <exception>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "episode/episode_config.h"
#include "episode/episode_result.h"
#include "geometry/vec2.h"
#include "planner/planner.h"
#include "robot/travel.h"
#include "worlds/world.h"

namespace plantsim::episode {

/// A controller from outside plantsim in the loop (the Python module's): `wrap` receives the
/// travel plantsim built, the robot's map and the first plan, and returns the travel to drive with
/// (one made by robot::steered_by). `name` is recorded in the result. Empty: plantsim's own
/// controller.
struct EpisodeSteering {
  std::string name;
  std::function<std::unique_ptr<robot::Travel>(std::unique_ptr<robot::Travel> builtin,
                                               const worlds::World& map,
                                               const std::vector<geom::Vec2>& first_plan)>
      wrap;
  /// Polled every control period (and by a batch between episodes): true stops the work (the
  /// Python module's Ctrl-C). Empty: never. Independent of `wrap`.
  std::function<bool()> interrupted;
  explicit operator bool() const { return static_cast<bool>(wrap); }
};

/// An episode that did not end by itself: stopped by `interrupted` (cause empty), or ended by an
/// exception from inside the loop (an outside controller's, in `cause`). Carries the episode so
/// far, recorded and closed as far as it went, and the simulated time it stopped at.
class EpisodeStopped : public std::runtime_error {
 public:
  EpisodeStopped(episode::EpisodeResult partial, double time_s, std::exception_ptr cause)
      : std::runtime_error(cause ? "the episode ended by an exception"
                                 : "the episode was interrupted"),
        partial(std::move(partial)),
        time_s(time_s),
        cause(std::move(cause)) {}
  episode::EpisodeResult partial;
  double time_s;
  std::exception_ptr cause;
};

/// `planner` plans the initial path; replans build fresh planners of the same name with the
/// sensed obstacles added. The loop: sense (sensor readings from the physics), estimate
/// (perception from readings and the map), decide (the travel mode), actuate, step, log. In a world
/// with a moving target the episode is a pursuit: the plan goes to where the target will park, and
/// success is reaching the target.
episode::EpisodeResult run_episode(const worlds::World& world, planner::Planner& planner,
                                   const episode::EpisodeConfig& config,
                                   const EpisodeSteering& steering = {});
// Throws EpisodeStopped when steering.interrupted asks it to stop or an exception leaves the
// loop (a controller's); bad input is refused before the loop as before.

}  // namespace plantsim::episode
