// The one home of geometric decisions in plantsim: exact orientation (adaptive filter with an
// exact expansion fallback, after Shewchuk), segment-versus-open-rectangle, point containment
// and local quadrant occupancy. Every answer is exact for the double inputs given: no
// tolerance constant exists here, so callers never need one for these questions.
#pragma once

#include "geometry/vec2.h"

namespace plantsim::geom {

enum class Orientation { kClockwise = -1, kCollinear = 0, kCounterClockwise = 1 };

/// Exact sign of cross(b - a, c - a): counter-clockwise when c lies left of a->b.
/// Assumes finite inputs whose products neither overflow nor underflow.
Orientation orient(Vec2 a, Vec2 b, Vec2 c);

/// True when x lies on segment [p, q] strictly between its endpoints (p != q assumed).
bool in_segment_interior(Vec2 p, Vec2 q, Vec2 x);

bool in_open_rect(const Rect& r, Vec2 p);
bool in_closed_rect(const Rect& r, Vec2 p);

/// True when the open interiors of a and b meet (touching edges do not count).
bool rects_overlap_open(const Rect& a, const Rect& b);

/// True when the closed segment [p, q] meets the open interior of r. Touching or sliding
/// along the boundary does not count. Exact (separating axes with strict comparisons).
bool segment_enters_open_rect(Vec2 p, Vec2 q, const Rect& r);

/// True when rectangle r covers the points c + (sx*e, sy*e) for every small e > 0, that is,
/// r fills the open quadrant (sx, sy) (signs +1/-1) right next to corner point c.
bool occupies_quadrant(const Rect& r, Vec2 c, int sx, int sy);

}  // namespace plantsim::geom
