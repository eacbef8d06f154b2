// The referee's verdict on a failed episode: it watches the truth (where the robot really is,
// how far its estimate is off) and the robot's side (its localisation health, whether it says
// it is blocked, why it gave up), and names one reason of robot/failure.h. Nothing here feeds
// back into sensing or control.
#pragma once

#include <optional>
#include <string>

#include "robot/failure.h"
#include "robot/pose_estimator.h"
#include "sim/integrity_watch.h"

namespace plantsim::sim {

struct FailureWatchParams {
  double stall_window_s =
      30.0;                    ///< no progress this long before the time ran out: stuck or blocked
  double progress_m = 0.5;     ///< moving this far from where it last progressed is progress
  double lost_error_m = 0.25;  ///< an estimate this far from the truth is lost, whatever it says
};

class FailureWatch {
 public:
  explicit FailureWatch(FailureWatchParams params = {}) : p_(params) {}
  /// Every control step: the truth, the estimate, its health, and whether the robot holds
  /// still because its way is blocked.
  void observe(double t_s, const geom::Pose2& truth, const geom::Pose2& estimate,
               robot::LocalizationHealth health, bool blocked);

  /// The verdict at the end (time `end_s`, true pose `end_pose`). `give_up`: the robot's own
  /// account when it stopped trying; `first_collision`: when and where the first contact
  /// began (true pose), if any; `breach`: the first drive on an estimate off the truth that
  /// the estimator did not notice, or past 1 m driven off in all (whichever of the two came
  /// first is the reason); `pursuit`:
  /// the episode chased a moving target.
  robot::Failure judge(double end_s, const geom::Pose2& end_pose,
                       const std::optional<robot::GiveUp>& give_up,
                       const std::optional<std::pair<double, geom::Pose2>>& first_collision,
                       const std::optional<IntegrityBreach>& breach, bool pursuit) const;

 private:
  struct Localisation {
    double error_m = 0;
    robot::LocalizationHealth health = robot::LocalizationHealth::kOk;
  };
  /// The estimate was lost, or far from the truth: say so in `detail`.
  bool lost(const Localisation& l, std::string& detail) const;

  FailureWatchParams p_;
  bool started_ = false;
  double anchor_s_ = 0;      // when it last progressed
  geom::Pose2 anchor_pose_;  // where
  Localisation at_anchor_;
  double blocked_since_anchor_s_ = 0;
  double last_s_ = 0;
  Localisation now_;
};

}  // namespace plantsim::sim
