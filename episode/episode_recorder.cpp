// The episode's record, from what each stage of the loop produced (see the header).
#include "episode/episode_recorder.h"

#include <algorithm>
#include <cmath>

#include "episode/log_thinning.h"

namespace plantsim::episode {

using namespace plantsim::sim;  // the simulator's parts

using robot::Decision;
using robot::Perception;

EpisodeRecorder::EpisodeRecorder(const worlds::World& plant, const EpisodeConfig& config,
                                 EpisodeResult& result)
    : config_(config),
      r_(result),
      metrics_(plant, result, config.step.dt_s),
      navigation_(plant, std::max(1, config.control_period_steps) * config.step.dt_s) {
  r_.status = EpisodeStatus::kTimeout;  // until something ends the episode sooner
  const auto max_steps = static_cast<std::int64_t>(std::ceil(config.timeout_s / config.step.dt_s));
  const std::int64_t max_samples = max_steps / std::max(1, config.control_period_steps) + 1;
  r_.trajectory.reserve(static_cast<std::size_t>(std::min<std::int64_t>(
      max_samples, static_cast<std::int64_t>(config.log_limits.trajectory))));
}

void EpisodeRecorder::planner_said(const planner::PlanResult& plan) {
  r_.plan_stats = plan.stats;
  r_.plan_trace = plan.trace;
  r_.plan_note = plan.note;
}

void EpisodeRecorder::first_plan(const planner::PlanResult& plan) {
  planner_said(plan);
  if (plan.status != planner::PlanStatus::kOk)
    r_.plan_note =
        "no reference plan (" + std::string(planner::to_string(plan.status)) + "): " + plan.note;
  r_.plan = plan.path;
  r_.first_plan = plan.path;
  r_.path_length_m = plan.length;
}

void EpisodeRecorder::no_way(const planner::PlanResult& plan, const Pose2& start) {
  planner_said(plan);
  r_.status = EpisodeStatus::kPlannerAnswer;
  r_.plan_status = plan.status;
  r_.failure = robot::Failure{
      robot::FailureReason::kNoPath, 0.0, start,
      "the planner: " + status_name(r_) + (plan.note.empty() ? "" : " (" + plan.note + ")")};
  event(Kind::kFailure, 0.0, start.position());
}

void EpisodeRecorder::not_started(const robot::Failure& why) {
  r_.status = EpisodeStatus::kFailed;
  r_.failure = why;
  event(Kind::kFailure, why.time_s, why.pose.position());
}

void EpisodeRecorder::before_step(const PhysicsWorld& physics, const ContactState& contact) {
  metrics_.before_step(physics, contact);
}

void EpisodeRecorder::after_step(const PhysicsWorld& physics) { metrics_.after_step(physics); }

void EpisodeRecorder::perceived(double t_s, const PhysicsWorld& physics, const Perception& p,
                                const robot::SensorReadings& readings) {
  metrics_.compare_estimate(physics, p.pose);
  metrics_.compare_obstacles(p.obstacles);
  metrics_.charging(physics, readings.charging);
  worst_health_ = std::max(worst_health_, p.health);  // ok < degraded < lost
  r_.time_s = t_s;
}

void EpisodeRecorder::caught(double t_s, const PhysicsWorld& physics, const Perception& p) {
  r_.caught = true;
  r_.status = EpisodeStatus::kCaught;
  sample(t_s, physics, p, nullptr);
}

void EpisodeRecorder::snapshot(double t_s, const Perception& p, const robot::Perceiver& perceiver) {
  if (config_.scan_log_period_s <= 0 || t_s < next_snapshot_s_) return;
  next_snapshot_s_ = t_s + config_.scan_log_period_s * r_.thinning.snapshots_every;
  r_.perception_log.push_back(
      {t_s, perceiver.last_scan(), perceiver.tracker().boxes(t_s), p.layer});
  if (r_.perception_log.size() >= std::max<std::size_t>(2, config_.log_limits.snapshots)) {
    keep_every_other(r_.perception_log);
    r_.thinning.snapshots_every *= 2;
  }
}

void EpisodeRecorder::decided(double t_s, const PhysicsWorld& physics, const Perception& p,
                              const Decision& d) {
  const Pose2 truth = physics.robot_pose();
  watch_.observe(t_s, truth, p.pose, p.health, d.blocked);
  integrity_.observe(t_s, truth, geom::dot(physics.robot_velocity(), truth.heading()), p.pose,
                     p.health);
  if (d.events.stopped) event(Kind::kStop, t_s, truth.position());
  if (d.events.replanned) event(Kind::kReplan, t_s, truth.position());
  if (d.events.recovered) event(Kind::kRecovery, t_s, truth.position());
  if (d.events.retried) event(Kind::kRetry, t_s, truth.position());
  track_moving_obstacles(t_s, physics);
  std::vector<geom::Rect> moving;
  for (const robot::ActorState& a : physics.actors()) moving.push_back(a.box);
  navigation_.sample(truth, geom::dot(physics.robot_velocity(), truth.heading()),
                     physics.robot_yaw_rate(), moving, d.phase == controller::DockPhase::kTravel);
  r_.max_cross_track_m = std::max(r_.max_cross_track_m, d.cross_track_m);
  sample(t_s, physics, p, &d);
  sketch(t_s);
}

void EpisodeRecorder::sketch(double t_s) {
  // Kept at the time of the step that made it; the next asked for a second after it (the log's
  // spacing), the controller answering at its next step whenever that is.
  if (std::optional<controller::TrajectorySketch> s = controller_clock_.take_sketch()) {
    r_.controller_sketches.push_back({t_s, std::move(*s)});
    if (r_.controller_sketches.size() >= std::max<std::size_t>(2, config_.log_limits.snapshots)) {
      keep_every_other(r_.controller_sketches);
      r_.thinning.sketches_every *= 2;
    }
    next_sketch_s_ = t_s + kSketchPeriod_s * r_.thinning.sketches_every;
  }
  if (t_s >= next_sketch_s_ && !controller_clock_.sketch_wanted()) controller_clock_.want_sketch();
}

void EpisodeRecorder::finished(const PhysicsWorld& physics, const Decision& d) {
  // Success is the charger's signal with no collision on the way (and, undocking, the staging
  // pose reached again), on estimates the robot could trust: one that drove on an estimate
  // 0.25 m off without knowing docked by luck (the charger's marker), not by design.
  const bool charged =
      d.finished == robot::TravelEnd::kDocked || d.finished == robot::TravelEnd::kUndocked;
  const bool breached = integrity_.record().breach.has_value();
  r_.docked = charged && r_.collisions == 0 && !breached;
  r_.undocked = d.finished == robot::TravelEnd::kUndocked;
  r_.status = !charged || r_.docked ? status_of(d.finished)
              : r_.collisions > 0   ? EpisodeStatus::kDockedWithCollision
                                    : EpisodeStatus::kDockedOffEstimate;
  if (!charged) metrics_.measure_final_error(physics);
  give_up_ = d.give_up;
}

void EpisodeRecorder::sample(double t_s, const PhysicsWorld& physics, const Perception& p,
                             const Decision* d) {
  // The last sample always; the others at the log's current spacing.
  const bool last = d == nullptr || d->finished != robot::TravelEnd::kNone;
  if (decisions_++ % r_.thinning.trajectory_every != 0 && !last) return;
  const Pose2 truth = physics.robot_pose();
  const double speed = geom::dot(physics.robot_velocity(), truth.heading());
  const std::optional<robot::ActorState> target = physics.target();
  const Vec2 target_at = target ? target->box.center() : Vec2{};
  if (d)
    r_.trajectory.push_back({t_s, truth, p.pose, p.position_sigma_m, speed, d->cross_track_m,
                             d->phase, d->wall_following, target_at, p.health});
  else
    r_.trajectory.push_back({t_s, truth, p.pose, p.position_sigma_m, speed, 0,
                             controller::DockPhase::kTravel, false, target_at, p.health});
  if (!last && r_.trajectory.size() >= std::max<std::size_t>(2, config_.log_limits.trajectory)) {
    keep_every_other(r_.trajectory);
    r_.thinning.trajectory_every *= 2;
  }
}

void EpisodeRecorder::event(Kind kind, double t_s, Vec2 at) {
  if (kind != Kind::kFailure && r_.events.size() >= config_.log_limits.events) {
    ++r_.thinning.events_dropped;
    return;
  }
  r_.events.push_back({kind, t_s, at});
}

void EpisodeRecorder::track_moving_obstacles(double t_s, const PhysicsWorld& physics) {
  constexpr double kMovingTrackPeriod_s = 0.25;
  if (t_s < next_track_s_) return;
  next_track_s_ = t_s + kMovingTrackPeriod_s * r_.thinning.moving_every;
  const std::vector<robot::ActorState> actors = physics.actors();
  if (actors.empty()) return;
  r_.moving_tracks.resize(actors.size());
  for (std::size_t i = 0; i < actors.size(); ++i) {
    r_.moving_tracks[i].t_s.push_back(t_s);
    r_.moving_tracks[i].boxes.push_back(actors[i].box);
  }
  const std::size_t samples = r_.moving_tracks.front().t_s.size();
  if (samples >= 2 && samples * actors.size() >= config_.log_limits.moving_boxes) {
    for (EpisodeResult::MovingTrack& track : r_.moving_tracks) {
      keep_every_other(track.t_s);
      keep_every_other(track.boxes);
    }
    r_.thinning.moving_every *= 2;
  }
}

void EpisodeRecorder::close(const PhysicsWorld& physics, const robot::Travel& travel,
                            const controller::TractionGovernor& governor,
                            const robot::Perceiver& perceiver, bool pursuit) {
  for (const robot::ActorState& a : physics.actors()) r_.moving_final.push_back(a.box);
  if (r_.status == EpisodeStatus::kTimeout) metrics_.measure_final_error(physics);
  r_.localization_status = std::string(to_string(worst_health_));
  r_.integrity = integrity_.record();
  const robot::TravelCounts counts = travel.counts();
  r_.retries = counts.retries;
  r_.stops = counts.stops;
  r_.replans = counts.replans;
  r_.local_minima = counts.local_minima;
  r_.wall_follows = counts.wall_follows;
  r_.recoveries = counts.recoveries;
  r_.slips = governor.slips();
  if (auto final_plan = travel.final_plan()) r_.plan = *final_plan;
  r_.last_scan = perceiver.last_scan();
  r_.relocalizations = perceiver.relocalizations();
  navigation_.write(r_);
  r_.controller_cycles = controller_clock_.cycles();
  r_.controller_ms_median = controller_clock_.quantile_ms(0.5);
  r_.controller_ms_p99 = controller_clock_.quantile_ms(0.99);
  r_.tracked_final = perceiver.tracker().boxes(r_.time_s);
  r_.layer_final = perceiver.current().layer;
  if (r_.succeeded()) return;
  r_.failure = watch_.judge(r_.time_s, physics.robot_pose(), give_up_, first_collision(physics),
                            pursuit ? std::nullopt : r_.integrity.breach, pursuit);
  event(Kind::kFailure, r_.failure->time_s, r_.failure->pose.position());
}

std::optional<std::pair<double, Pose2>> EpisodeRecorder::first_collision(
    const PhysicsWorld& physics) const {
  for (const EpisodeResult::Event& e : r_.events) {
    if (e.kind != Kind::kCollision) continue;
    // The heading from the last logged sample at or before the contact (the event keeps a
    // position).
    double yaw = physics.robot_pose().yaw;
    for (const TrajectorySample& s : r_.trajectory)
      if (s.t_s <= e.t_s) yaw = s.truth.yaw;
    return std::pair{e.t_s, Pose2{e.at.x, e.at.y, yaw}};
  }
  return std::nullopt;
}

}  // namespace plantsim::episode
