// Truth into metrics.
#include "episode/episode_metrics.h"

#include <cmath>

#include "geometry/predicates.h"

namespace plantsim::episode {

EpisodeMetrics::EpisodeMetrics(const worlds::World& plant, EpisodeResult& result, double dt_s)
    : plant_(plant),
      r_(result),
      dt_s_(dt_s),
      previous_(plant.start.position()),
      unmapped_seen_(plant.unmapped.size(), 0) {}

void EpisodeMetrics::before_step(const PhysicsWorld& physics, const ContactState& contact) {
  if (contact.obstacle && !was_touching_obstacle_) {
    ++r_.collisions;
    r_.events.push_back({EpisodeResult::Event::Kind::kCollision, r_.physics_steps * dt_s_,
                         physics.robot_position()});
    // Whose doing: the robot's when it was moving towards what it touched (faster than a
    // creep), not when something walked into a standing or retreating robot.
    // The motion over the last steps before contact (the solver has already stopped the
    // robot's approach velocity by the time the contact is seen).
    const Vec2 at = physics.robot_position();
    const Vec2 v =
        recent_.empty() ? Vec2{0, 0} : (1.0 / (recent_.size() * dt_s_)) * (at - recent_.front());
    bool driving_into = false;
    for (const Vec2& p : contact.obstacle_points) {
      const Vec2 d = p - at;
      const double len = geom::norm(d);
      if (len > 0 && geom::dot(v, d) / len > 0.02) driving_into = true;
    }
    r_.collisions_robot_moving += driving_into;
  }
  was_touching_obstacle_ = contact.obstacle;
}

void EpisodeMetrics::charging(const PhysicsWorld& physics, bool on) {
  // The pose errors are those at the moment charging starts (the first time, if it starts again).
  if (on && !charging_measured_) measure_final_error(physics);
  charging_measured_ = charging_measured_ || on;
  r_.charging = r_.charging || on;
}

void EpisodeMetrics::after_step(const PhysicsWorld& physics) {
  ++r_.physics_steps;
  const Vec2 now = physics.robot_position();
  r_.driven_length_m += geom::distance(previous_, now);
  previous_ = now;
  recent_.push_back(now);
  if (recent_.size() > 6) recent_.pop_front();
}

void EpisodeMetrics::carried(double t_s, const Pose2& from, const Pose2& to) {
  r_.carries.push_back({t_s, from, to});
  previous_ = to.position();
  recent_.clear();  // a contact right after landing is judged on the motion after it
}

void EpisodeMetrics::compare_estimate(const PhysicsWorld& physics, const Pose2& estimate) {
  r_.localization_error_max_m = std::max(
      r_.localization_error_max_m, geom::distance(physics.robot_position(), estimate.position()));
}

void EpisodeMetrics::compare_obstacles(const std::vector<controller::MovingBox>& perceived) {
  for (std::size_t i = 0; i < plant_.unmapped.size(); ++i) {
    if (unmapped_seen_[i]) continue;
    // Sensed: some perceived box overlaps it (a face seen is enough; the boxes carry the
    // tracker's assumed depth and the layer's cell size, so a small tolerance is not needed).
    for (const auto& b : perceived)
      if (geom::rects_overlap_open(b.box, plant_.unmapped[i])) {
        unmapped_seen_[i] = 1;
        ++r_.unmapped_seen;
        break;
      }
  }
}

void EpisodeMetrics::measure_final_error(const PhysicsWorld& physics) {
  if (plant_.target)
    return;  // a pursuit ends at its target, not at the charger: nothing to measure
  const Pose2 truth = physics.robot_pose();
  r_.position_error_m = geom::distance(truth.position(), plant_.charger.position());
  r_.heading_error_deg = std::fabs(geom::wrap_angle(truth.yaw - plant_.charger.yaw)) * 180.0 / M_PI;
  r_.error_measured = true;
  r_.measured_pose = truth;
}

}  // namespace plantsim::episode
