// A rectangle grown by a disk of radius d (open, d shrunk by the tolerance) is the union of two
// open rectangles (grown along x only, along y only) and four open disks at its corners; an arc
// enters it when it enters one of the six.
#include "geometry/clearance.h"

#include <algorithm>
#include <cmath>

namespace plantsim::geom {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;

// True when angle t lies on the arc from `from` counter-clockwise through `sweep`.
bool on_arc(double t, double from, double sweep) {
  double off = std::fmod(t - from, kTwoPi);
  if (off < 0) off += kTwoPi;
  return off <= sweep;
}

// True when some point of the arc lies strictly inside the open disk (q, d).
bool arc_enters_disk(Vec2 c, double radius, double from, double sweep, Vec2 q, double d) {
  const double l = distance(c, q);
  if (l >= radius + d || l == 0) return false;  // l == 0: every arc point is at radius >= d
  // |c + radius u(t) - q| < d  <=>  cos(t - phi) > k
  const double k = (radius * radius + l * l - d * d) / (2 * radius * l);
  if (k >= 1) return false;
  const double phi = std::atan2(q.y - c.y, q.x - c.x);
  if (k < -1) return true;
  const double beta = std::acos(k);
  // Two arcs on the circle meet when one contains the other's start.
  return on_arc(phi - beta, from, sweep) || on_arc(from, phi - beta, 2 * beta);
}

// True when some point of the arc lies strictly inside the open rectangle e.
bool arc_enters_open_rect(Vec2 c, double radius, double from, double sweep, const Rect& e) {
  if (!(e.xmin < e.xmax && e.ymin < e.ymax)) return false;
  auto inside = [&](Vec2 p) {
    return e.xmin < p.x && p.x < e.xmax && e.ymin < p.y && p.y < e.ymax;
  };
  if (inside(c + radius * unit_from_angle(from)) ||
      inside(c + radius * unit_from_angle(from + sweep)))
    return true;
  // Otherwise the arc enters only by crossing an edge: where the circle meets an edge's line
  // inside the edge and on the arc (a tangent touch does not enter).
  auto crosses_vertical = [&](double x) {
    const double v = (x - c.x) / radius;
    if (!(v > -1 && v < 1)) return false;
    const double t = std::acos(v);
    for (double a : {t, -t}) {
      const double y = c.y + radius * std::sin(a);
      if (e.ymin < y && y < e.ymax && on_arc(a, from, sweep)) return true;
    }
    return false;
  };
  auto crosses_horizontal = [&](double y) {
    const double v = (y - c.y) / radius;
    if (!(v > -1 && v < 1)) return false;
    const double t = std::asin(v);
    for (double a : {t, M_PI - t}) {
      const double x = c.x + radius * std::cos(a);
      if (e.xmin < x && x < e.xmax && on_arc(a, from, sweep)) return true;
    }
    return false;
  };
  return crosses_vertical(e.xmin) || crosses_vertical(e.xmax) || crosses_horizontal(e.ymin) ||
         crosses_horizontal(e.ymax);
}

// The closed parameter interval of the segment p + t d, t in [0, 1], inside the closed rectangle
// (Liang-Barsky); empty (lo > hi) when they do not meet.
std::pair<double, double> span_in_rect(Vec2 p, Vec2 d, const Rect& r) {
  double t0 = 0, t1 = 1;
  auto clip = [&](double denom, double num) {  // keeps t with denom * t <= num
    if (denom == 0) return num >= 0;
    const double t = num / denom;
    if (denom > 0)
      t1 = std::min(t1, t);
    else
      t0 = std::max(t0, t);
    return t0 <= t1;
  };
  if (clip(-d.x, p.x - r.xmin) && clip(d.x, r.xmax - p.x) && clip(-d.y, p.y - r.ymin) &&
      clip(d.y, r.ymax - p.y))
    return {t0, t1};
  return {1, 0};
}

// The same inside the closed disk (c, radius): |p + t d - c|^2 <= radius^2.
std::pair<double, double> span_in_disk(Vec2 p, Vec2 d, Vec2 c, double radius) {
  const Vec2 f = p - c;
  const double a = dot(d, d), b = dot(f, d), k = dot(f, f) - radius * radius;
  if (a == 0) return k <= 0 ? std::pair{0.0, 1.0} : std::pair{1.0, 0.0};
  const double disc = b * b - a * k;
  if (disc < 0) return {1, 0};
  const double root = std::sqrt(disc);
  return {std::max(0.0, (-b - root) / a), std::min(1.0, (-b + root) / a)};
}

}  // namespace

std::optional<std::pair<double, double>> segment_span_within(Vec2 p, Vec2 q, const Rect& r,
                                                             double d) {
  // The grown rectangle is the union of two rectangles and four disks; the union of their spans
  // is one interval because the grown rectangle is convex.
  const Vec2 v = q - p;
  double lo = 2, hi = -1;
  auto take = [&](std::pair<double, double> s) {
    if (s.first > s.second) return;
    lo = std::min(lo, s.first);
    hi = std::max(hi, s.second);
  };
  take(span_in_rect(p, v, {r.xmin - d, r.ymin, r.xmax + d, r.ymax}));
  take(span_in_rect(p, v, {r.xmin, r.ymin - d, r.xmax, r.ymax + d}));
  for (Vec2 k :
       {Vec2{r.xmin, r.ymin}, Vec2{r.xmax, r.ymin}, Vec2{r.xmax, r.ymax}, Vec2{r.xmin, r.ymax}})
    take(span_in_disk(p, v, k, d));
  if (lo > hi) return std::nullopt;
  return std::pair{lo, hi};
}

double distance_to_rect(Vec2 p, const Rect& r) { return distance(p, closest_point(r, p)); }

double segment_rect_distance(Vec2 p, Vec2 q, const Rect& r) {
  const Vec2 d = q - p;
  if (const auto [t0, t1] = span_in_rect(p, d, r); t0 <= t1) return 0;  // they meet
  // Apart, a convex rectangle and a segment are nearest at an endpoint of one of them.
  double best = std::min(distance_to_rect(p, r), distance_to_rect(q, r));
  const double dd = dot(d, d);
  for (Vec2 k :
       {Vec2{r.xmin, r.ymin}, Vec2{r.xmax, r.ymin}, Vec2{r.xmax, r.ymax}, Vec2{r.xmin, r.ymax}}) {
    const double t = dd > 0 ? std::clamp(dot(k - p, d) / dd, 0.0, 1.0) : 0.0;
    best = std::min(best, distance(k, p + t * d));
  }
  return best;
}

bool arc_keeps_clearance(Vec2 c, double radius, double from, double sweep, const Rect& r,
                         double clearance) {
  const double d = clearance - kClearanceTolerance_m;
  if (d <= 0) return true;
  // Far apart: the whole circle keeps the clearance.
  if (distance_to_rect(c, r) >= radius + d) return true;
  if (arc_enters_open_rect(c, radius, from, sweep, {r.xmin - d, r.ymin, r.xmax + d, r.ymax}) ||
      arc_enters_open_rect(c, radius, from, sweep, {r.xmin, r.ymin - d, r.xmax, r.ymax + d}))
    return false;
  for (Vec2 k :
       {Vec2{r.xmin, r.ymin}, Vec2{r.xmax, r.ymin}, Vec2{r.xmax, r.ymax}, Vec2{r.xmin, r.ymax}})
    if (arc_enters_disk(c, radius, from, sweep, k, d)) return false;
  return true;
}

}  // namespace plantsim::geom
