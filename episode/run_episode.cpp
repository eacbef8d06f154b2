// One episode run to its end in one call (the loop itself: episode_loop.h).
#include "episode/run_episode.h"

#include <chrono>

#include "episode/episode_loop.h"

namespace plantsim::episode {

episode::EpisodeResult run_episode(const worlds::World& plant, planner::Planner& planner,
                                   const episode::EpisodeConfig& config,
                                   const EpisodeSteering& steering) {
  const auto began = std::chrono::steady_clock::now();
  EpisodeRun run(plant, planner, config, steering);
  EpisodeRun::Stop stop = EpisodeRun::Stop::kEnded;
  try {
    stop = run.advance(steering.interrupted);
  } catch (...) {
    throw EpisodeStopped(std::move(run.result()), run.time_s(), std::current_exception());
  }
  if (stop == EpisodeRun::Stop::kInterrupted) {
    run.result().status = EpisodeStatus::kInterrupted;
    throw EpisodeStopped(std::move(run.result()), run.time_s(), nullptr);
  }
  run.result().wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return std::move(run.result());
}

}  // namespace plantsim::episode
