// Progress, blocking and localisation watched over the episode; one reason at the end.
#include "sim/failure_watch.h"

#include <cstdio>

#include "util/c_number.h"

namespace plantsim::sim {

using robot::Failure;
using robot::FailureReason;
using robot::GiveUp;
using robot::LocalizationHealth;

void FailureWatch::observe(double t_s, const geom::Pose2& truth, const geom::Pose2& estimate,
                           LocalizationHealth health, bool blocked) {
  now_ = {geom::distance(truth.position(), estimate.position()), health};
  if (!started_ || geom::distance(truth.position(), anchor_pose_.position()) > p_.progress_m) {
    started_ = true;
    anchor_s_ = t_s;
    anchor_pose_ = truth;
    at_anchor_ = now_;
    blocked_since_anchor_s_ = 0;
  } else if (blocked) {
    blocked_since_anchor_s_ += t_s - last_s_;
  }
  last_s_ = t_s;
}

bool FailureWatch::lost(const Localisation& l, std::string& detail) const {
  if (l.health != LocalizationHealth::kLost && l.error_m <= p_.lost_error_m) return false;
  char text[160];
  util::c_snprintf(text, sizeof text,
                   "the estimate was %.2f m from the true position, its status %s", l.error_m,
                   std::string(to_string(l.health)).c_str());
  detail = text;
  return true;
}

Failure FailureWatch::judge(double end_s, const geom::Pose2& end_pose,
                            const std::optional<GiveUp>& give_up,
                            const std::optional<std::pair<double, geom::Pose2>>& first_collision,
                            const std::optional<IntegrityBreach>& breach, bool pursuit) const {
  Failure f;
  if (breach && (!first_collision || breach->time_s <= first_collision->first)) {
    // It drove on an estimate it should not have trusted: whatever followed came of that.
    f.reason = FailureReason::kLocalizationLost;
    f.time_s = breach->time_s;
    f.pose = breach->pose;
    char text[200];
    if (breach->kind == BreachKind::kDrivenOff)
      util::c_snprintf(text, sizeof text,
                       "drove %.1f m in all on an estimate more than 0.25 m off (worst %.2f m), "
                       "whatever its estimator reported",
                       breach->driven_off_m, breach->worst_error_m);
    else
      util::c_snprintf(text, sizeof text,
                       "drove on an estimate more than 0.25 m off (worst %.2f m) for %.1f s "
                       "without reporting itself lost",
                       breach->worst_error_m, breach->unnoticed_s);
    f.detail = text;
    return f;
  }
  if (first_collision) {
    // Success needs an episode without contact, whatever happened after it.
    f.reason = FailureReason::kCollision;
    f.time_s = first_collision->first;
    f.pose = first_collision->second;
    f.detail = "the first contact with an obstacle or a wall";
    return f;
  }
  f.time_s = end_s;
  f.pose = end_pose;
  Localisation then = now_;
  if (give_up) {
    f.reason = give_up->reason;
    f.detail = give_up->detail;
  } else if (pursuit) {
    f.reason = FailureReason::kTargetLost;
    f.detail = "the target was not caught in time";
  } else if (started_ && end_s - anchor_s_ >= p_.stall_window_s) {
    // It stood (or shuffled within progress_m) for the whole window before the time ran out.
    const bool blocked = blocked_since_anchor_s_ >= 0.5 * (end_s - anchor_s_);
    f.reason = blocked ? FailureReason::kBlocked : FailureReason::kStuck;
    f.time_s = anchor_s_;
    f.pose = anchor_pose_;
    then = at_anchor_;
    char text[160];
    util::c_snprintf(text, sizeof text, "no progress for the last %.0f s, %s", end_s - anchor_s_,
                     blocked ? "held by what blocked its way" : "not held by anything it saw");
    f.detail = text;
  } else {
    f.reason = FailureReason::kTimeout;
    f.detail = "still moving on when the time ran out";
  }
  // A robot that did not know where it was failed for that, whatever it then did.
  std::string why;
  if (f.reason != FailureReason::kTrapped && f.reason != FailureReason::kPluginError &&
      (lost(then, why) || lost(now_, why))) {
    f.detail = why + " (" + std::string(to_string(f.reason)) + ": " + f.detail + ")";
    f.reason = FailureReason::kLocalizationLost;
  }
  return f;
}

}  // namespace plantsim::sim
