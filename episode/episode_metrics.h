// The episode's metrics, measured from the simulator's truth as the loop steps it (collisions and
// whose doing, pose error at contact, driven length, localisation error); the
// referee's verdicts are sim/failure_watch.h and sim/integrity_watch.h. Nothing here feeds back
// into sensing or control.
#pragma once

#include <deque>
#include <vector>

#include "episode/episode_result.h"
#include "sim/physics_world.h"

namespace plantsim::episode {

using sim::ContactState;
using sim::PhysicsWorld;

class EpisodeMetrics {
 public:
  EpisodeMetrics(const worlds::World& plant, EpisodeResult& result, double dt_s);
  /// Every physics step, before it, with the contacts the last step left: collisions.
  void before_step(const PhysicsWorld& physics, const ContactState& contact);
  /// Every physics step, after it: driven length.
  void after_step(const PhysicsWorld& physics);
  /// A fault set the robot down elsewhere (a kidnap): a carry, not driven length.
  void carried(double t_s, const Pose2& from, const Pose2& to);
  /// At each control step: how far the estimate is from the truth.
  void compare_estimate(const PhysicsWorld& physics, const Pose2& estimate);
  /// At each control step: which unmapped obstacles perception's obstacles cover (sensed).
  void compare_obstacles(const std::vector<controller::MovingBox>& perceived);
  /// At each control step, the charger's signal: the pose error when charging starts.
  void charging(const PhysicsWorld& physics, bool on);
  /// The pose error now (for episodes ending without charging).
  void measure_final_error(const PhysicsWorld& physics);

 private:
  const worlds::World& plant_;
  EpisodeResult& r_;
  bool was_touching_obstacle_ = false;
  bool charging_measured_ = false;
  double dt_s_;
  Vec2 previous_;
  std::deque<Vec2> recent_;          // positions after the last few steps
  std::vector<char> unmapped_seen_;  // per unmapped obstacle of the plant
};

}  // namespace plantsim::episode
