// The episode's loop as a machine that can pause: the parts (physics, drive, sensors, perceiver,
// travel, traction) assembled from the plant, the robot's map and the configuration, run step by
// step until the episode ends, an outside stop is asked for, or a decision awaits an outside
// command (the step-wise environment of the Python module). run_episode runs it to the end in one
// call; SteppedEpisode pauses it at every decision an outside controller makes.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "episode/episode_config.h"
#include "episode/episode_recorder.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "worlds/world.h"

namespace plantsim::episode {

/// One episode from its first plan to its end: the robot's map, the recorder and the loop's
/// parts. Holds references into itself: neither copied nor moved.
class EpisodeRun {
 public:
  enum class Stop { kEnded, kInterrupted, kAwaitingCommand };

  /// Plans from the start and assembles the parts; `steering` wraps the travel (may be empty).
  EpisodeRun(const worlds::World& plant, planner::Planner& planner,
             const episode::EpisodeConfig& config, const EpisodeSteering& steering);
  ~EpisodeRun();
  EpisodeRun(const EpisodeRun&) = delete;
  EpisodeRun& operator=(const EpisodeRun&) = delete;

  /// Runs on from where it stands. `interrupted` is polled every control period (true stops
  /// it); `wants_command`, asked after each decision that does not end the episode, pauses the
  /// loop with that decision awaiting command() when true. Either may be empty. An exception
  /// from inside the loop leaves after the episode so far is recorded and closed.
  Stop advance(const std::function<bool()>& interrupted,
               const std::function<bool()>& wants_command = {});
  /// The awaited decision's twist (before the traction limits, as the travel's own would be).
  void command(controller::Twist twist);

  episode::EpisodeResult& result() { return result_; }
  double time_s() const;
  /// The robot's perception at the last control period, or none before the first.
  const robot::Perception* last_perception() const;

 private:
  class Loop;
  episode::EpisodeResult result_;
  worlds::World map_copy_;    // the robot's map when it differs from the plant
  const worlds::World& map_;  // map_copy_ or the plant
  std::unique_ptr<EpisodeRecorder> recorder_;
  // The local controller's entry with its calls timed (controller_clock.h): the travel holds a
  // pointer to it, so it outlives the loop.
  std::unique_ptr<controller::LocalControllerEntry> timed_local_;
  std::unique_ptr<Loop> loop_;  // none when the episode ended at its first plan
};

}  // namespace plantsim::episode
