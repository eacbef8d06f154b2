// The true footprint's clearance (see the header).
#include "episode/footprint_clearance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "geometry/clearance.h"

namespace plantsim::episode {
namespace {

using geom::Pose2;
using geom::Rect;
using geom::Vec2;

/// The rectangle's corners at `pose`, counter-clockwise.
std::array<Vec2, 4> corners(const worlds::RobotSpec& robot, const Pose2& pose) {
  const double hl = 0.5 * robot.length_m, hw = 0.5 * robot.width_m;
  const Vec2 c = pose.position();
  return {c + geom::rotate({hl, hw}, pose.yaw), c + geom::rotate({-hl, hw}, pose.yaw),
          c + geom::rotate({-hl, -hw}, pose.yaw), c + geom::rotate({hl, -hw}, pose.yaw)};
}

/// True when p lies inside the convex counter-clockwise quadrilateral q (or on its boundary).
bool inside(const std::array<Vec2, 4>& q, Vec2 p) {
  for (std::size_t i = 0; i < 4; ++i)
    if (geom::cross(q[(i + 1) % 4] - q[i], p - q[i]) < 0) return false;
  return true;
}

}  // namespace

FootprintClearance::FootprintClearance(const worlds::World& plant)
    : robot_(plant.robot), floor_(plant.floor), boxes_(plant.obstacles) {
  boxes_.insert(boxes_.end(), plant.unmapped.begin(), plant.unmapped.end());
}

double FootprintClearance::to_box(const Pose2& pose, const Rect& box, double best) const {
  // The circumscribed disk's distance is a lower bound for a rectangle, exact for a disk.
  const double disk = geom::distance_to_rect(pose.position(), box) - robot_.radius_m;
  if (!robot_.rectangular() || disk >= best) return std::max(0.0, disk);
  const std::array<Vec2, 4> q = corners(robot_, pose);
  // A box wholly inside the footprint touches no edge: it overlaps all the same.
  if (inside(q, {0.5 * (box.xmin + box.xmax), 0.5 * (box.ymin + box.ymax)})) return 0.0;
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < 4; ++i)
    d = std::min(d, geom::segment_rect_distance(q[i], q[(i + 1) % 4], box));
  return d;
}

double FootprintClearance::to_walls(const Pose2& pose) const {
  auto inner = [&](Vec2 p) {
    return std::min(std::min(p.x - floor_.xmin, floor_.xmax - p.x),
                    std::min(p.y - floor_.ymin, floor_.ymax - p.y));
  };
  if (!robot_.rectangular()) return std::max(0.0, inner(pose.position()) - robot_.radius_m);
  double d = std::numeric_limits<double>::infinity();
  for (const Vec2& c : corners(robot_, pose)) d = std::min(d, inner(c));
  return std::max(0.0, d);
}

double FootprintClearance::at(const Pose2& pose, const std::vector<Rect>& moving) const {
  double best = to_walls(pose);
  for (const Rect& b : boxes_) best = std::min(best, to_box(pose, b, best));
  for (const Rect& b : moving) best = std::min(best, to_box(pose, b, best));
  return best;
}

}  // namespace plantsim::episode
