// The failure reasons' names.
#include "robot/failure.h"

namespace plantsim::robot {

std::string_view to_string(FailureReason r) {
  switch (r) {
    case FailureReason::kCollision:
      return "collision";
    case FailureReason::kLocalizationLost:
      return "localization_lost";
    case FailureReason::kNoPath:
      return "no_path";
    case FailureReason::kBlocked:
      return "blocked";
    case FailureReason::kStuck:
      return "stuck";
    case FailureReason::kDockRetriesExhausted:
      return "dock_retries_exhausted";
    case FailureReason::kUndockFailed:
      return "undock_failed";
    case FailureReason::kTargetLost:
      return "target_lost";
    case FailureReason::kTrapped:
      return "trapped";
    case FailureReason::kTimeout:
      return "timeout";
    case FailureReason::kPluginError:
      return "plugin_error";
  }
  return "unknown";
}

std::optional<FailureReason> failure_reason_from_string(std::string_view text) {
  for (FailureReason r : kAllFailureReasons)
    if (to_string(r) == text) return r;
  return std::nullopt;
}

}  // namespace plantsim::robot
