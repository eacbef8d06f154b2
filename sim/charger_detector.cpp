// Visibility, noise, misses, outliers and latency of the charger detection.
#include "sim/charger_detector.h"

#include <cmath>

#include "sim/physics_world.h"

namespace plantsim::sim {

using robot::ChargerDetection;

ChargerDetector::ChargerDetector(DetectionParams params, std::uint64_t seed)
    : p_(params), noise_(seed ^ 0x9e3779b97f4a7c15ULL) {}

std::optional<geom::Pose2> ChargerDetector::observe(const PhysicsWorld& physics,
                                                    const geom::Pose2& robot_truth,
                                                    const geom::Pose2& dock_truth,
                                                    geom::Vec2 marker) {
  const geom::Pose2 camera = geom::compose(robot_truth, {p_.mount_x_m, 0, 0});
  const geom::Vec2 to_marker = marker - camera.position();
  if (geom::dot(to_marker, to_marker) > p_.range_m * p_.range_m) return std::nullopt;
  const geom::Vec2 m = geom::rotate(to_marker, -camera.yaw);
  if (std::fabs(std::atan2(m.y, m.x)) > 0.5 * p_.field_of_view_rad) return std::nullopt;
  if (p_.occlusion) {
    // The marker is on the face: the sight line, run a little past it, must meet the charger first.
    const double d = geom::norm(to_marker);
    const geom::Vec2 beyond = camera.position() + ((d + 0.02) / std::max(d, 1e-9)) * to_marker;
    const auto hit = physics.ray_cast(camera.position(), beyond);
    if (!hit || hit->kind != SurfaceKind::kCharger) return std::nullopt;
  }
  // Draws for every visible image, in a fixed order, so the random stream does not depend on
  // which branch was taken.
  const double miss = noise_.uniform(), outlier = noise_.uniform();
  const double ex = noise_.gaussian(), ey = noise_.gaussian(), eyaw = noise_.gaussian();
  if (miss < p_.false_negative_probability) return std::nullopt;
  const bool gross = outlier < p_.outlier_probability;
  const double sp = gross ? p_.outlier_position_m : p_.position_noise_m;
  const double sy = gross ? p_.outlier_yaw_rad : p_.yaw_noise_rad;
  const geom::Vec2 rel =
      geom::rotate(dock_truth.position() - robot_truth.position(), -robot_truth.yaw);
  return geom::Pose2{rel.x + sp * ex, rel.y + sp * ey,
                     geom::wrap_angle(dock_truth.yaw - robot_truth.yaw + sy * eyaw)};
}

std::optional<ChargerDetection> ChargerDetector::update(const PhysicsWorld& physics,
                                                        const geom::Pose2& robot_truth,
                                                        const geom::Pose2& dock_truth,
                                                        geom::Vec2 marker, double t_s) {
  if (!p_.enabled) return std::nullopt;
  if (t_s + 1e-9 >= next_image_s_) {
    next_image_s_ = t_s + 1.0 / p_.rate_hz;
    if (auto seen = observe(physics, robot_truth, dock_truth, marker))
      pending_.push_back({t_s, *seen});
  }
  std::optional<ChargerDetection> out;
  while (!pending_.empty() && pending_.front().captured_s + p_.latency_s <= t_s + 1e-9) {
    out = pending_.front();  // the newest ready one wins
    pending_.pop_front();
  }
  return out;
}

}  // namespace plantsim::sim
