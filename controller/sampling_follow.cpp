// Progress, bearing and the local distance field for the sampling controllers.
#include "controller/sampling_follow.h"

#include <cmath>

namespace plantsim::controller {

PathProgress::PathProgress(std::vector<Vec2> path) : path_(std::move(path)) {}

void PathProgress::update(const Pose2& pose, double carrot_m, double goal_tolerance_m,
                          TrackingCommand& out) {
  if (path_.empty()) {
    out.goal_reached = true;
    return;
  }
  if (path_.size() == 1) {
    out.goal_reached = geom::distance(pose.position(), path_[0]) <= goal_tolerance_m;
    return;
  }
  const PathPoint here = closest_point(path_, pose.position(), segment_, 2.0);
  segment_ = here.segment;
  out.cross_track_error_m = here.distance;
  const Vec2 carrot = to_robot_frame(pose, point_ahead(path_, here, carrot_m));
  out.carrot_bearing_rad = std::atan2(carrot.y, carrot.x);
  out.goal_reached = geom::distance(pose.position(), path_.back()) <= goal_tolerance_m;
}

Pose2 PathProgress::goal() const {
  if (path_.empty()) return {};
  if (path_.size() == 1) return {path_[0].x, path_[0].y, 0.0};
  const Vec2 a = path_[path_.size() - 2], b = path_.back();
  return {b.x, b.y, std::atan2(b.y - a.y, b.x - a.x)};
}

void SamplingController::set_path(std::vector<Vec2> path) {
  set_method_path(path);
  progress_ = PathProgress(std::move(path));
}

TrackingCommand SamplingController::step(const LocalQuery& q) {
  TrackingCommand out;
  progress_.update(q.pose, 0.5, goal_tolerance_m_, out);
  if (out.goal_reached) return out;
  const ClearanceGrid field = local_clearance(ctx_, q, 3.0, 0.05, field_reach_m_);
  out.twist = sample(q, field, progress_.goal());
  return out;
}

ClearanceGrid local_clearance(const LocalControllerContext& ctx, const LocalQuery& q,
                              double half_side_m, double cell_m, double reach_m) {
  // Boxes beyond the window and the field's reach (its own half side) change no cell.
  const Vec2 c = q.pose.position();
  const double reach = 2.0 * half_side_m;
  const geom::Rect near{c.x - reach, c.y - reach, c.x + reach, c.y + reach};
  std::vector<geom::Rect> boxes;
  auto add = [&](const geom::Rect& r) {
    if (r.xmax >= near.xmin && r.xmin <= near.xmax && r.ymax >= near.ymin && r.ymin <= near.ymax)
      boxes.push_back(r);
  };
  for (const geom::Rect& r : ctx.map_obstacles) add(r);
  if (q.nearby_obstacles)
    for (const MovingBox& m : *q.nearby_obstacles) add(m.box);
  return ClearanceGrid(c, half_side_m, cell_m, boxes, ctx.floor, reach_m);
}

}  // namespace plantsim::controller
