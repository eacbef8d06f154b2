// The search for a recognisable view while lost (see lost_search.h).
#include "robot/lost_search.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "robot/scan_points.h"

namespace plantsim::robot {
namespace {

std::vector<geom::Vec2> returns_within(const LidarScan& scan, double reach_m) {
  std::vector<geom::Vec2> out = scan_points(scan, static_cast<int>(scan.ranges.size()));
  std::erase_if(out,
                [&](geom::Vec2 q) { return geom::distance(q, scan.mount.position()) > reach_m; });
  return out;
}

}  // namespace

void LostSearch::reset() {
  turned_rad_ = 0;
  last_yaw_.reset();
  target_yaw_.reset();
  leg_start_.reset();
  driven_ = false;
}

double LostSearch::free_ahead(const LidarScan& scan, double heading, double clearance_m) const {
  // Outside the field of view (less a margin for the disk's width) nothing is known: not free.
  const double half_fov =
      0.5 * std::fabs(scan.angle_increment_rad) * static_cast<double>(scan.ranges.size());
  const double centre = scan.mount.yaw + scan.angle_min_rad + half_fov;
  if (std::fabs(geom::wrap_angle(heading - centre)) > half_fov - 0.3) return 0;
  const geom::Vec2 u = geom::unit_from_angle(heading);
  const double half_width = radius_ + clearance_m;
  double free = scan.max_range_m;
  for (const geom::Vec2& q : scan_points(scan, static_cast<int>(scan.ranges.size()))) {
    const double along = geom::dot(u, q), across = geom::cross(u, q);
    if (along > -radius_ && std::fabs(across) < half_width)
      free = std::min(free, std::max(0.0, along - half_width));
  }
  return free;
}

namespace {

constexpr double kMinFree = 1.5;  // a leg needs this much free way ahead

struct Surface {
  geom::Vec2 nearest;  // the nearest return, robot frame
  geom::Vec2 along;    // the surface's direction there
};

/// The nearest surface among `seen` (not empty): its direction is the principal axis of the
/// returns within 1.5 m of the nearest.
Surface nearest_surface(const std::vector<geom::Vec2>& seen) {
  const geom::Vec2 nearest =
      *std::min_element(seen.begin(), seen.end(),
                        [](geom::Vec2 a, geom::Vec2 b) { return geom::norm(a) < geom::norm(b); });
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  int n = 0;
  for (const geom::Vec2& q : seen)
    if (geom::distance(q, nearest) <= 1.5) {
      mean += Eigen::Vector2d(q.x, q.y);
      ++n;
    }
  mean /= n;
  for (const geom::Vec2& q : seen)
    if (geom::distance(q, nearest) <= 1.5) {
      const Eigen::Vector2d d = Eigen::Vector2d(q.x, q.y) - mean;
      scatter += d * d.transpose();
    }
  geom::Vec2 along{-nearest.y, nearest.x};  // one return: the surface faces the robot
  if (n >= 3) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(scatter);
    along = {eig.eigenvectors()(0, 1), eig.eigenvectors()(1, 1)};
  }
  return {nearest, along};
}

}  // namespace

std::optional<double> LostSearch::along_surface(const LidarScan& scan, double clearance_m,
                                                bool keep_standoff) const {
  const std::vector<geom::Vec2> seen = returns_within(scan, p_.surface_reach_m);
  if (seen.empty()) {  // nothing in reach: straight on, if the way is free
    return free_ahead(scan, 0.0, clearance_m) >= kMinFree ? std::optional(0.0) : std::nullopt;
  }
  const Surface surface = nearest_surface(seen);
  std::optional<double> best;
  for (const double sign : {1.0, -1.0}) {
    const geom::Vec2 u{sign * surface.along.x, sign * surface.along.y};
    double heading = std::atan2(u.y, u.x);
    if (keep_standoff) {  // steer towards the surface when far from it, away when near
      const double side = geom::cross(u, surface.nearest) > 0 ? 1.0 : -1.0;
      const double off = std::fabs(geom::cross(u, surface.nearest));
      heading += side * std::clamp(0.3 * (off - p_.standoff_m), -0.4, 0.4);
    }
    if (free_ahead(scan, heading, clearance_m) < kMinFree) continue;
    // The way nearer the robot's facing: it carries on along the surface leg after leg.
    if (!best || std::fabs(geom::wrap_angle(heading)) < std::fabs(geom::wrap_angle(*best)))
      best = geom::wrap_angle(heading);
  }
  return best;
}

std::optional<LostSearch::Leg> LostSearch::choose_leg(const LidarScan& scan) const {
  if (const auto heading = along_surface(scan, p_.clearance_m, true))
    return Leg{*heading, p_.clearance_m};
  // Between two surfaces nearer than the stand-off and the clearance allow (a corridor),
  // steering off one points at the other: straight along the surface with less clearance, or
  // else the freest way in view.
  const double narrow = std::min(p_.narrow_clearance_m, p_.clearance_m);
  if (const auto heading = along_surface(scan, narrow, false)) return Leg{*heading, narrow};
  std::optional<Leg> best;
  double most = kMinFree;
  for (double heading = -M_PI; heading < M_PI; heading += 0.1)
    if (const double free = free_ahead(scan, heading, narrow); free >= most) {
      most = free;
      best = Leg{heading, narrow};
    }
  return best;
}

controller::Twist LostSearch::step(const LidarScan& scan, const geom::Pose2& odom) {
  if (last_yaw_) turned_rad_ += std::fabs(geom::wrap_angle(odom.yaw - *last_yaw_));
  last_yaw_ = odom.yaw;
  const controller::Twist turn{0.0, p_.turn_radps};
  // A full turn on the spot first: the scans see all round, and most kidnaps are found by it.
  if (!driven_ && turned_rad_ < 2.0 * M_PI) return turn;
  if (!target_yaw_) {
    const std::optional<Leg> leg = choose_leg(scan);
    if (!leg) return turn;  // nothing to follow, no way free: look round again
    target_yaw_ = geom::wrap_angle(odom.yaw + leg->heading);
    leg_clearance_m_ = leg->clearance_m;
    leg_start_.reset();
  }
  const double error = geom::wrap_angle(*target_yaw_ - odom.yaw);
  if (!leg_start_ && std::fabs(error) > 0.15) return {0.0, std::copysign(p_.turn_radps, error)};
  if (!leg_start_) leg_start_ = odom.position();
  driven_ = true;
  const double stopping = p_.speed_mps * p_.speed_mps / 2.0 + 0.2;
  if (geom::distance(odom.position(), *leg_start_) >= p_.leg_m ||
      free_ahead(scan, 0.0, leg_clearance_m_) < stopping) {
    target_yaw_.reset();  // the leg is done (or the way closes): choose again next step
    leg_start_.reset();
    return {};
  }
  return {p_.speed_mps, std::clamp(1.5 * error, -p_.turn_radps, p_.turn_radps)};
}

}  // namespace plantsim::robot
