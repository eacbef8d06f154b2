// The episode's status: from travel's end, and as the records spell it.
#include "episode/episode_result.h"

namespace plantsim::episode {

EpisodeStatus status_of(robot::TravelEnd end) {
  switch (end) {
    case robot::TravelEnd::kDocked:
      return EpisodeStatus::kDocked;
    case robot::TravelEnd::kUndocked:
      return EpisodeStatus::kUndocked;
    case robot::TravelEnd::kFailed:
      return EpisodeStatus::kFailed;
    case robot::TravelEnd::kTrapped:
      return EpisodeStatus::kTrapped;
    case robot::TravelEnd::kNone:
      break;
  }
  return EpisodeStatus::kTimeout;
}

std::string status_name(const EpisodeOutcome& outcome) {
  switch (outcome.status) {
    case EpisodeStatus::kTimeout:
      return "timeout";
    case EpisodeStatus::kDocked:
      return "docked";
    case EpisodeStatus::kUndocked:
      return "undocked";
    case EpisodeStatus::kDockedWithCollision:
      return "docked_with_collision";
    case EpisodeStatus::kDockedOffEstimate:
      return "docked_off_estimate";
    case EpisodeStatus::kCaught:
      return "caught";
    case EpisodeStatus::kFailed:
      return "failed";
    case EpisodeStatus::kTrapped:
      return "trapped";
    case EpisodeStatus::kInterrupted:
      return "interrupted";
    case EpisodeStatus::kPlannerAnswer:
      break;
  }
  return std::string(planner::to_string(outcome.plan_status));
}

}  // namespace plantsim::episode
