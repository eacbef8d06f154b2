// Plain 2-D value types shared by every module: points/vectors, poses and axis-aligned
// rectangles, in metres and radians (x right, y up, angles counter-clockwise).
// Predicates that decide geometry questions live in predicates.h, not here.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace plantsim::geom {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
  friend Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
  friend bool operator==(Vec2 a, Vec2 b) = default;  // exact; no tolerance (not transitive)
};

inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }  // not hypot: 5x slower
inline double distance(Vec2 a, Vec2 b) { return norm(b - a); }
inline Vec2 unit_from_angle(double angle_rad) { return {std::cos(angle_rad), std::sin(angle_rad)}; }
inline Vec2 rotate(Vec2 v, double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

/// Wraps an angle to (-pi, pi].
inline double wrap_angle(double angle_rad) {
  // Already in (-pi, pi): the value itself, as remainder would give it, without remainder's
  // rounding-mode switches (the particle filter wraps every particle's heading every scan).
  if (std::fabs(angle_rad) < M_PI) return angle_rad;
  double a = std::remainder(angle_rad, 2.0 * M_PI);
  if (a <= -M_PI) a += 2.0 * M_PI;
  return a;
}

struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;  ///< heading, radians, counter-clockwise from +x

  Vec2 position() const { return {x, y}; }
  Vec2 heading() const { return unit_from_angle(yaw); }
};

/// Rigid transforms as poses (the pose of a child frame in its parent): a then b.
inline Pose2 compose(const Pose2& a, const Pose2& b) {
  const Vec2 p = a.position() + rotate(b.position(), a.yaw);
  return {p.x, p.y, wrap_angle(a.yaw + b.yaw)};
}
inline Pose2 inverse(const Pose2& a) {
  const Vec2 p = rotate(Vec2{-a.x, -a.y}, -a.yaw);
  return {p.x, p.y, wrap_angle(-a.yaw)};
}

/// Closed axis-aligned rectangle [xmin, xmax] x [ymin, ymax].
struct Rect {
  double xmin = 0.0;
  double ymin = 0.0;
  double xmax = 0.0;
  double ymax = 0.0;

  double width() const { return xmax - xmin; }
  double height() const { return ymax - ymin; }
  Vec2 center() const { return {0.5 * (xmin + xmax), 0.5 * (ymin + ymax)}; }
  Rect inflated(double margin) const {
    return {xmin - margin, ymin - margin, xmax + margin, ymax + margin};
  }
  friend bool operator==(const Rect&, const Rect&) = default;
};

/// Whether the closed rectangle `outer` holds all of `inner` (exact comparisons).
inline bool holds(const Rect& outer, const Rect& inner) {
  return inner.xmin >= outer.xmin && inner.xmax <= outer.xmax && inner.ymin >= outer.ymin &&
         inner.ymax <= outer.ymax;
}

/// The part of r within `to` (empty, with xmin > xmax or ymin > ymax, when they do not meet).
inline Rect clipped(const Rect& r, const Rect& to) {
  return {std::max(r.xmin, to.xmin), std::max(r.ymin, to.ymin), std::min(r.xmax, to.xmax),
          std::min(r.ymax, to.ymax)};
}

/// The point of the closed rectangle nearest to p (p itself when inside).
inline Vec2 closest_point(const Rect& r, Vec2 p) {
  return {p.x < r.xmin ? r.xmin : (p.x > r.xmax ? r.xmax : p.x),
          p.y < r.ymin ? r.ymin : (p.y > r.ymax ? r.ymax : p.y)};
}

/// The point of the segment ab nearest to p (a when the segment is a point).
inline Vec2 closest_point_on_segment(Vec2 a, Vec2 b, Vec2 p) {
  const Vec2 d = b - a;
  const double dd = dot(d, d);
  const double t = dd > 0 ? std::clamp(dot(p - a, d) / dd, 0.0, 1.0) : 0.0;
  return a + t * d;
}

/// Four rectangles of the given thickness surrounding `inner` (left, right, bottom, top),
/// overlapping at the corners: a floor's boundary as solid walls.
inline std::array<Rect, 4> surrounding_walls(const Rect& inner, double thickness) {
  const Rect& f = inner;
  const double t = thickness;
  return {Rect{f.xmin - t, f.ymin - t, f.xmin, f.ymax + t},
          Rect{f.xmax, f.ymin - t, f.xmax + t, f.ymax + t},
          Rect{f.xmin - t, f.ymin - t, f.xmax + t, f.ymin},
          Rect{f.xmin - t, f.ymax, f.xmax + t, f.ymax + t}};
}

}  // namespace plantsim::geom
