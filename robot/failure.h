// Why an episode did not succeed: one reason from a closed, documented set (docs/failures.md),
// with when and where (true pose) it happened. The referee (sim/failure_watch.h) decides it from
// the truth and from what the robot's side reported; nothing here feeds back into control.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "geometry/vec2.h"

namespace plantsim::robot {

enum class FailureReason {
  kCollision,         ///< touched an obstacle or a wall (success needs none)
  kLocalizationLost,  ///< the estimate was lost, or far (> 0.25 m) from the truth, when it failed
  kNoPath,            ///< the planner found no way (or start or goal blocked, or past its budget)
  kBlocked,           ///< the way stayed blocked after its replans (or the back-off did)
  kStuck,             ///< no progress: it stopped moving (never settled, slipping on the spot)
  kDockRetriesExhausted,  ///< every allowed docking approach missed
  kUndockFailed,          ///< charged, but could not back out to the staging pose
  kTargetLost,            ///< a pursuit that never caught its target
  kTrapped,               ///< seed 001's potential field met too many local minima
  kTimeout,               ///< still making progress when the time ran out
  kPluginError,           ///< a plugin's component threw (its message is the detail)
};
inline constexpr std::array kAllFailureReasons{
    FailureReason::kCollision,    FailureReason::kLocalizationLost,
    FailureReason::kNoPath,       FailureReason::kBlocked,
    FailureReason::kStuck,        FailureReason::kDockRetriesExhausted,
    FailureReason::kUndockFailed, FailureReason::kTargetLost,
    FailureReason::kTrapped,      FailureReason::kTimeout,
    FailureReason::kPluginError};

std::string_view to_string(FailureReason r);
/// The reason named `text` (as to_string writes it), or none.
std::optional<FailureReason> failure_reason_from_string(std::string_view text);

/// What the robot's side said when it gave up.
struct GiveUp {
  FailureReason reason;
  std::string detail;
};

/// The verdict on an episode that did not succeed.
struct Failure {
  FailureReason reason = FailureReason::kTimeout;
  double time_s =
      0;  ///< when it happened (the first collision, the robot giving up, the last progress)
  geom::Pose2 pose;    ///< the true pose then
  std::string detail;  ///< one sentence more (the planner's status, the robot's own account)
};

}  // namespace plantsim::robot
