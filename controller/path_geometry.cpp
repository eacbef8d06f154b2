// Polyline helpers for the path tracker.
#include "controller/path_geometry.h"

#include <algorithm>
#include <cmath>

namespace plantsim::controller {

PathPoint closest_point(const std::vector<Vec2>& path, Vec2 p, std::size_t from_segment,
                        double window_m) {
  PathPoint best;
  best.point = path.front();
  best.distance = geom::distance(p, path.front());
  if (path.size() < 2) return best;
  best.distance = INFINITY;
  // The window counts path beyond the current segment, however long that segment is.
  const std::size_t first = std::min(from_segment, path.size() - 2);
  double scanned = 0;
  for (std::size_t i = first; i + 1 < path.size(); ++i) {
    const Vec2 a = path[i], b = path[i + 1];
    const Vec2 ab = b - a;
    const double len2 = geom::dot(ab, ab);
    const double t = len2 > 0 ? std::clamp(geom::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const Vec2 q = a + t * ab;
    const double d = geom::distance(p, q);
    if (d < best.distance) best = {i, t, q, d};
    if (i > first) scanned += std::sqrt(len2);
    if (scanned > window_m) break;
  }
  return best;
}

namespace {

double turn_at(const std::vector<Vec2>& path, std::size_t vertex) {
  const Vec2 a = path[vertex] - path[vertex - 1], b = path[vertex + 1] - path[vertex];
  return std::fabs(std::atan2(geom::cross(a, b), geom::dot(a, b)));
}

}  // namespace

bool sharp_vertex(const std::vector<Vec2>& path, std::size_t vertex, double sharp_turn_rad) {
  return vertex > 0 && vertex + 1 < path.size() && turn_at(path, vertex) > sharp_turn_rad;
}

Vec2 point_ahead(const std::vector<Vec2>& path, const PathPoint& from, double ahead_m,
                 double sharp_turn_rad, double corner_release_m) {
  if (path.size() < 2) return path.front();
  Vec2 cur = from.point;
  double left = ahead_m, walked = 0;
  for (std::size_t i = from.segment; i + 1 < path.size(); ++i) {
    const double seg = geom::distance(cur, path[i + 1]);
    if (seg >= left && seg > 0) return cur + (left / seg) * (path[i + 1] - cur);
    left -= seg;
    walked += seg;
    cur = path[i + 1];
    if (i + 2 < path.size() && turn_at(path, i + 1) > sharp_turn_rad && walked > corner_release_m)
      return cur;
  }
  return path.back();
}

double distance_to_sharp_corner(const std::vector<Vec2>& path, const PathPoint& from,
                                double sharp_turn_rad, double horizon_m) {
  if (path.size() < 2) return 0;
  Vec2 cur = from.point;
  double walked = 0;
  for (std::size_t i = from.segment; i + 1 < path.size() && walked < horizon_m; ++i) {
    walked += geom::distance(cur, path[i + 1]);
    cur = path[i + 1];
    if (i + 2 < path.size() && turn_at(path, i + 1) > sharp_turn_rad) return walked;
  }
  return walked;
}

std::vector<double> lengths_to_end(const std::vector<Vec2>& path) {
  std::vector<double> out(path.size(), 0.0);
  for (std::size_t i = path.size(); i-- > 1;)
    out[i - 1] = out[i] + geom::distance(path[i - 1], path[i]);
  return out;
}

double remaining_length(const std::vector<Vec2>& path, const std::vector<double>& to_end,
                        const PathPoint& from) {
  if (path.size() < 2) return 0;
  return geom::distance(from.point, path[from.segment + 1]) + to_end[from.segment + 1];
}

Vec2 to_robot_frame(const Pose2& pose, Vec2 p) {
  return geom::rotate(p - pose.position(), -pose.yaw);
}

}  // namespace plantsim::controller
