// Arc sampling against boxes.
#include "controller/collision_check.h"

#include <algorithm>
#include <cmath>

#include "geometry/predicates.h"

namespace plantsim::controller {

double distance_to_box(geom::Vec2 p, const geom::Rect& r) {
  return geom::distance(p, geom::closest_point(r, p));
}

double segment_distance_to_box(geom::Vec2 a, geom::Vec2 b, const geom::Rect& r) {
  if (geom::in_closed_rect(r, a) || geom::segment_enters_open_rect(a, b, r)) return 0.0;
  // Apart, the nearest pair has an endpoint of the segment or a corner of the box in it.
  double d = std::min(distance_to_box(a, r), distance_to_box(b, r));
  const geom::Vec2 corners[] = {
      {r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}};
  for (const geom::Vec2& c : corners)
    d = std::min(d, geom::distance(c, geom::closest_point_on_segment(a, b, c)));
  return d;
}

bool arc_clear(const geom::Pose2& pose, Twist twist, double travel_speed_mps, double distance_m,
               double radius_m, const std::vector<MovingBox>& boxes, double horizon_s,
               double step_m) {
  if (boxes.empty()) return true;
  const double direction = twist.v_mps >= 0 ? 1.0 : -1.0;
  const double curvature = std::fabs(twist.v_mps) > 1e-9 ? twist.omega_radps / twist.v_mps : 0.0;
  const int samples =
      std::fabs(twist.v_mps) > 1e-9 ? static_cast<int>(std::ceil(distance_m / step_m)) : 0;
  // A box already inside the margin does not forbid every motion: one that moves away from it
  // (never closer than now) is how the robot gets out.
  std::vector<double> allowed(boxes.size());
  for (std::size_t j = 0; j < boxes.size(); ++j)
    allowed[j] = std::min(radius_m, distance_to_box(pose.position(), boxes[j].box));
  for (int i = 0; i <= samples; ++i) {
    const double s = direction * i * step_m;  // signed arc length
    geom::Vec2 p;
    if (std::fabs(curvature) < 1e-9) {
      p = pose.position() + s * pose.heading();
    } else {
      const double dtheta = s * curvature;
      p = pose.position() +
          (1.0 / curvature) * geom::Vec2{std::sin(pose.yaw + dtheta) - std::sin(pose.yaw),
                                         -std::cos(pose.yaw + dtheta) + std::cos(pose.yaw)};
    }
    const double t =
        std::min(horizon_s, travel_speed_mps > 0 ? std::fabs(s) / travel_speed_mps : 0.0);
    for (std::size_t j = 0; j < boxes.size(); ++j) {
      const MovingBox& b = boxes[j];
      const geom::Vec2 d = t * b.velocity;
      const geom::Rect moved{b.box.xmin + d.x, b.box.ymin + d.y, b.box.xmax + d.x,
                             b.box.ymax + d.y};
      if (distance_to_box(p, moved) < allowed[j]) return false;
    }
  }
  return true;
}

bool position_threatened(geom::Vec2 position, double radius_m, const std::vector<MovingBox>& boxes,
                         double horizon_s, double step_s) {
  for (const MovingBox& b : boxes)
    for (double t = 0; t <= horizon_s; t += step_s) {
      const geom::Vec2 d = t * b.velocity;
      if (distance_to_box(position, {b.box.xmin + d.x, b.box.ymin + d.y, b.box.xmax + d.x,
                                     b.box.ymax + d.y}) < radius_m)
        return true;
    }
  return false;
}

}  // namespace plantsim::controller
