// Integrity measured period by period: each period's state holds until the next observation.
#include "sim/integrity_watch.h"

#include <algorithm>
#include <cmath>

namespace plantsim::sim {

void IntegrityWatch::observe(double t_s, const geom::Pose2& truth, double true_speed_mps,
                             const geom::Pose2& estimate, robot::LocalizationHealth health) {
  const double dt = started_ ? t_s - last_s_ : 0.0;
  started_ = true;
  last_s_ = t_s;
  const double error = geom::distance(truth.position(), estimate.position());
  const bool moving = std::abs(true_speed_mps) > p_.moving_mps;
  const bool lost = health == robot::LocalizationHealth::kLost;
  if (moving) {
    record_.worst_moving_error_m = std::max(record_.worst_moving_error_m, error);
    if (error > p_.off_m) {
      record_.driven_off_s += dt;
      record_.driven_off_m += std::abs(true_speed_mps) * dt;  // a kidnap's carry has no speed
    }
  }
  judge_distance(t_s, truth);
  if (health == robot::LocalizationHealth::kOk && error > p_.ok_off_m) record_.ok_while_off_s += dt;
  if (health != robot::LocalizationHealth::kOk) record_.not_ok_s += dt;

  if (error <= p_.off_m || lost) {  // on the truth again, or the estimator said so
    in_stretch_ = false;
    return;
  }
  if (!in_stretch_) {
    in_stretch_ = true;
    drove_in_stretch_ = false;
    stretch_ = IntegrityBreach{t_s, truth, error, 0.0};
  }
  stretch_.worst_error_m = std::max(stretch_.worst_error_m, error);
  stretch_.unnoticed_s = t_s - stretch_.time_s;
  // Driving counts once the grace is over: a displacement is the estimator's to notice first.
  if (stretch_.unnoticed_s > p_.grace_s && moving) drove_in_stretch_ = true;
  // The unnoticed stretch is dated from its start: it names the breach when that came first.
  const bool earlier = !record_.breach || (record_.breach->kind == BreachKind::kDrivenOff &&
                                           stretch_.time_s < record_.breach->time_s);
  if (drove_in_stretch_ && earlier) record_.breach = stretch_;
  if (record_.breach && record_.breach->kind == BreachKind::kUnnoticed &&
      record_.breach->time_s == stretch_.time_s)
    record_.breach = stretch_;
}

void IntegrityWatch::judge_distance(double t_s, const geom::Pose2& truth) {
  if (record_.breach && record_.breach->kind == BreachKind::kDrivenOff) {
    record_.breach->worst_error_m = record_.worst_moving_error_m;  // the totals run on
    record_.breach->driven_off_m = record_.driven_off_m;
    return;
  }
  if (record_.breach || record_.driven_off_m <= p_.max_driven_off_m) return;
  IntegrityBreach b;
  b.time_s = t_s;
  b.pose = truth;
  b.worst_error_m = record_.worst_moving_error_m;
  b.kind = BreachKind::kDrivenOff;
  b.driven_off_m = record_.driven_off_m;
  record_.breach = b;
}

}  // namespace plantsim::sim
