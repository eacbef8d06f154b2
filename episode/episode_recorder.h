// The episode's record: everything an episode writes into its result besides driving the robot,
// the trajectory log, the events, the perception snapshots, the moving obstacles' tracks, the
// referee's metrics (episode_metrics.h) and its verdict on a failure (failure_watch.h). The loop
// (episode_loop.cpp) hands it what each stage produced and decides when the episode ends (the
// travel's decision, or the referee's catch rule); nothing here feeds back into the robot.
#pragma once

#include <cstdint>
#include <optional>

#include "controller/traction.h"
#include "episode/controller_clock.h"
#include "episode/episode_config.h"
#include "episode/episode_metrics.h"
#include "episode/episode_result.h"
#include "episode/navigation_metrics.h"
#include "planner/planner.h"
#include "robot/perception.h"
#include "robot/travel.h"
#include "sim/failure_watch.h"
#include "sim/integrity_watch.h"

namespace plantsim::episode {

// The simulator's side the recorder reads (the truth, for the referee), by their own names.
using geom::Pose2;
using geom::Vec2;
using sim::ContactState;

using sim::FailureWatch;
using sim::PhysicsWorld;

class EpisodeRecorder {
 public:
  EpisodeRecorder(const worlds::World& plant, const EpisodeConfig& config, EpisodeResult& result);

  /// The plan the robot sets off on and what the planner said about it (a travel that needs
  /// no plan sets off without one).
  void first_plan(const planner::PlanResult& plan);
  /// The planner found no way for a travel that needs one: the episode ended at `start`.
  void no_way(const planner::PlanResult& plan, const Pose2& start);
  /// The episode ended before its first step for `why` (a plugin's factory threw).
  void not_started(const robot::Failure& why);

  /// Every physics step, before and after it (collisions, driven length).
  void before_step(const PhysicsWorld& physics, const ContactState& contact);
  void after_step(const PhysicsWorld& physics);
  /// A fault carried the robot from `from` and set it down at `to` (a kidnap).
  void carried(double t_s, const Pose2& from, const Pose2& to) {
    metrics_.carried(t_s, from, to);
    navigation_.carried();
  }
  /// Where the local controller's step calls are timed (timed_entry): the referee's clock.
  ControllerClock& controller_clock() { return controller_clock_; }

  /// Every control step, once perception has spoken: its errors against the truth, its health.
  void perceived(double t_s, const PhysicsWorld& physics, const robot::Perception& p,
                 const robot::SensorReadings& readings);
  /// The moving target caught (the loop ends the episode here): the status and a last sample.
  void caught(double t_s, const PhysicsWorld& physics, const robot::Perception& p);
  /// A snapshot of what perception saw, at the log's spacing.
  void snapshot(double t_s, const robot::Perception& p, const robot::Perceiver& perceiver);
  /// The travel's decision: the trajectory sample and the events the travel reported.
  void decided(double t_s, const PhysicsWorld& physics, const robot::Perception& p,
               const robot::Decision& d);
  /// The decision ended the travel (the loop ends the episode here): the status and the
  /// referee's view of how it ended.
  void finished(const PhysicsWorld& physics, const robot::Decision& d);
  /// At the end: the counts, the robot's last view, and the referee's verdict on a failure.
  void close(const PhysicsWorld& physics, const robot::Travel& travel,
             const controller::TractionGovernor& governor, const robot::Perceiver& perceiver,
             bool pursuit);

 private:
  /// What every first plan leaves behind, a way found or not: its statistics, trace and note.
  void planner_said(const planner::PlanResult& plan);
  using Kind = EpisodeResult::Event::Kind;
  void event(Kind kind, double t_s, Vec2 at);
  /// One trajectory sample; `d` null when the episode ended before a decision.
  void sample(double t_s, const PhysicsWorld& physics, const robot::Perception& p,
              const robot::Decision* d);
  void track_moving_obstacles(double t_s, const PhysicsWorld& physics);
  /// The controller's last sketch kept, and the next asked for (controller_clock.h).
  void sketch(double t_s);
  static constexpr double kSketchPeriod_s = 1.0;
  std::optional<std::pair<double, Pose2>> first_collision(const PhysicsWorld& physics) const;

  const EpisodeConfig& config_;
  EpisodeResult& r_;
  EpisodeMetrics metrics_;
  NavigationMetrics navigation_;
  ControllerClock controller_clock_;
  FailureWatch watch_;
  sim::IntegrityWatch integrity_;
  robot::LocalizationHealth worst_health_ = robot::LocalizationHealth::kOk;
  std::optional<robot::GiveUp> give_up_;
  double next_snapshot_s_ = 0;
  double next_sketch_s_ = 0;
  double next_track_s_ = 0;
  std::int64_t decisions_ = 0;  // trajectory samples offered (one per control period)
};

}  // namespace plantsim::episode
