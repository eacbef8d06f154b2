// Regulated pure pursuit step.
#include "controller/pure_pursuit.h"

#include <algorithm>
#include <cmath>

namespace plantsim::controller {

PurePursuit::PurePursuit(PurePursuitParams params, std::vector<Vec2> path)
    : params_(params), path_(std::move(path)), to_end_(lengths_to_end(path_)) {}

TrackingCommand PurePursuit::step(const Pose2& pose, double current_speed_mps) {
  TrackingCommand out;
  const PurePursuitParams& p = params_;
  PathPoint near = closest_point(path_, pose.position(), segment_, p.progress_window_m);
  // The distance from the path counts the leg before the current one too: after a corner's
  // release moved progress on, a robot turning in place just short of the corner is on the
  // path, not off the next leg.
  const double off_path =
      segment_ > 0
          ? closest_point(path_, pose.position(), segment_ - 1, p.progress_window_m).distance
          : near.distance;
  // Within the release distance of a sharp vertex the corner counts as reached: progress moves
  // on to the next leg. Otherwise, where the path doubles back on itself (a dead end, a lane
  // swept twice), the closest point would stay on the leg behind and the robot would turn to
  // and fro at the vertex.
  const std::size_t vertex = near.segment + 1;
  if (sharp_vertex(path_, vertex, p.sharp_turn_rad) &&
      geom::distance(pose.position(), path_[vertex]) <= p.corner_release_m)
    near = closest_point(path_, pose.position(), vertex, p.progress_window_m);
  segment_ = near.segment;
  out.cross_track_error_m = std::min(off_path, near.distance);
  const double remaining = remaining_length(path_, to_end_, near);
  const double to_end = geom::distance(pose.position(), path_.back());
  // Done when at the end, or when the end lies behind the robot within the tolerance band
  // (never turn around for the last centimetres).
  const Vec2 end_in_robot = to_robot_frame(pose, path_.back());
  if (to_end <= p.goal_tolerance_m || (remaining <= p.goal_tolerance_m && end_in_robot.x <= 0)) {
    out.goal_reached = true;
    return out;
  }

  const double lookahead = std::clamp(std::fabs(current_speed_mps) * p.lookahead_time_s,
                                      p.lookahead_min_m, p.lookahead_max_m);
  const Vec2 carrot = point_ahead(path_, near, lookahead, p.sharp_turn_rad, p.corner_release_m);
  const Vec2 c = to_robot_frame(pose, carrot);
  const double heading_error = std::atan2(c.y, c.x);
  out.carrot_bearing_rad = heading_error;
  if (std::fabs(heading_error) > p.rotate_in_place_threshold_rad) rotating_ = true;
  if (std::fabs(heading_error) < p.rotate_in_place_exit_rad) rotating_ = false;
  if (rotating_) {
    const double w = std::min(p.rotate_in_place_speed_radps, 2.0 * std::fabs(heading_error));
    out.twist = {0.0, std::copysign(w, heading_error)};
    return out;
  }
  const double d2 = geom::dot(c, c);
  const double curvature = d2 > 0 ? 2.0 * c.y / d2 : 0.0;

  double v = p.max_linear_speed_mps;
  const double radius = std::fabs(curvature) > 0 ? 1.0 / std::fabs(curvature) : INFINITY;
  if (radius < p.regulated_min_radius_m) v *= radius / p.regulated_min_radius_m;
  // Slow down for the path's end and for sharp corners, where the robot turns in place.
  const double to_stop = std::min(
      remaining,
      distance_to_sharp_corner(path_, near, p.sharp_turn_rad, p.approach_slowdown_distance_m));
  out.straight_ahead_m =
      std::min(remaining, distance_to_sharp_corner(path_, near, p.sharp_turn_rad, 5.0));
  if (to_stop < p.approach_slowdown_distance_m)
    v = std::min(v, p.max_linear_speed_mps * to_stop / p.approach_slowdown_distance_m);
  v = std::max(v, p.min_approach_speed_mps);
  double omega = v * curvature;
  if (std::fabs(omega) > p.max_angular_speed_radps) {
    omega = std::copysign(p.max_angular_speed_radps, omega);
    v = omega / curvature;
  }
  out.twist = {v, omega};
  return out;
}

}  // namespace plantsim::controller
