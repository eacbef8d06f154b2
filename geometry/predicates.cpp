// Exact predicates. orient() first tries the plain double determinant with a proven error
// bound (Shewchuk's ccwerrboundA) and, only when that cannot decide the sign, evaluates the
// determinant exactly as a floating-point expansion built from error-free sums and products.
#include "geometry/predicates.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace plantsim::geom {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon() / 2.0;  // 2^-53
constexpr double kCcwErrBoundA = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kSplitter = 134217729.0;  // 2^27 + 1, Veltkamp split of a double

struct Pair {
  double hi;
  double lo;
};

// a + b == hi + lo exactly (Knuth's two-sum).
Pair two_sum(double a, double b) {
  const double s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  return {s, (a - av) + (b - bv)};
}

Pair split(double a) {
  const double c = kSplitter * a;
  const double hi = c - (c - a);
  return {hi, a - hi};
}

// a * b == hi + lo exactly (Dekker's two-product; no FMA needed).
Pair two_product(double a, double b) {
  const double p = a * b;
  const Pair as = split(a), bs = split(b);
  const double err = p - as.hi * bs.hi - as.lo * bs.hi - as.hi * bs.lo;
  return {p, as.lo * bs.lo - err};
}

// Sign of the exact sum of terms, via Shewchuk's Grow-Expansion: the components stay
// non-overlapping and sorted by magnitude, so the last non-zero one carries the sign.
int exact_sum_sign(const std::array<double, 12>& terms) {
  std::array<double, 13> h{};
  int n = 0;
  for (double x : terms) {
    double q = x;
    for (int i = 0; i < n; ++i) {
      const Pair s = two_sum(q, h[i]);
      q = s.hi;
      h[i] = s.lo;
    }
    h[n++] = q;
  }
  for (int i = n - 1; i >= 0; --i) {
    if (h[i] > 0) return 1;
    if (h[i] < 0) return -1;
  }
  return 0;
}

int orient_exact(Vec2 a, Vec2 b, Vec2 c) {
  // cross(b - a, c - a) = bx*cy - bx*ay - ax*cy - by*cx + by*ax + ay*cx
  const Pair p[6] = {two_product(b.x, c.y),  two_product(-b.x, a.y), two_product(-a.x, c.y),
                     two_product(-b.y, c.x), two_product(b.y, a.x),  two_product(a.y, c.x)};
  std::array<double, 12> terms{};
  for (int i = 0; i < 6; ++i) {
    terms[2 * i] = p[i].lo;
    terms[2 * i + 1] = p[i].hi;
  }
  return exact_sum_sign(terms);
}

}  // namespace

Orientation orient(Vec2 a, Vec2 b, Vec2 c) {
  const double det_left = (a.x - c.x) * (b.y - c.y);
  const double det_right = (a.y - c.y) * (b.x - c.x);
  const double det = det_left - det_right;
  const double bound = kCcwErrBoundA * (std::fabs(det_left) + std::fabs(det_right));
  int sign;
  if (det > bound) {
    sign = 1;
  } else if (-det > bound) {
    sign = -1;
  } else {
    sign = orient_exact(a, b, c);
  }
  return static_cast<Orientation>(sign);
}

bool in_segment_interior(Vec2 p, Vec2 q, Vec2 x) {
  if (orient(p, q, x) != Orientation::kCollinear) return false;
  if (p.x != q.x) return std::min(p.x, q.x) < x.x && x.x < std::max(p.x, q.x);
  return std::min(p.y, q.y) < x.y && x.y < std::max(p.y, q.y);
}

bool in_open_rect(const Rect& r, Vec2 p) {
  return r.xmin < p.x && p.x < r.xmax && r.ymin < p.y && p.y < r.ymax;
}

bool rects_overlap_open(const Rect& a, const Rect& b) {
  return a.xmin < b.xmax && b.xmin < a.xmax && a.ymin < b.ymax && b.ymin < a.ymax;
}

bool in_closed_rect(const Rect& r, Vec2 p) {
  return r.xmin <= p.x && p.x <= r.xmax && r.ymin <= p.y && p.y <= r.ymax;
}

bool segment_enters_open_rect(Vec2 p, Vec2 q, const Rect& r) {
  // Axes x and y: the closed projection of the segment must overlap the open one of r.
  if (std::max(p.x, q.x) <= r.xmin || std::min(p.x, q.x) >= r.xmax) return false;
  if (std::max(p.y, q.y) <= r.ymin || std::min(p.y, q.y) >= r.ymax) return false;
  if (p == q) return in_open_rect(r, p);
  // Axis normal to the segment: some corner strictly on each side of its line.
  const Vec2 corners[4] = {{r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}};
  bool left = false, right = false;
  for (const Vec2& c : corners) {
    const Orientation o = orient(p, q, c);
    left |= o == Orientation::kCounterClockwise;
    right |= o == Orientation::kClockwise;
  }
  return left && right;
}

bool occupies_quadrant(const Rect& r, Vec2 c, int sx, int sy) {
  const bool x_ok = sx > 0 ? (r.xmin <= c.x && c.x < r.xmax) : (r.xmin < c.x && c.x <= r.xmax);
  const bool y_ok = sy > 0 ? (r.ymin <= c.y && c.y < r.ymax) : (r.ymin < c.y && c.y <= r.ymax);
  return x_ok && y_ok;
}

}  // namespace plantsim::geom
