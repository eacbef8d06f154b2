// Clearance of a disk among axis-aligned rectangles: how far a point or a segment is from a
// rectangle, and whether a circular arc keeps a given distance from one. These decide the round
// inflation's free space (a rectangle grown by a disk, rounded corners); unlike predicates.h
// they involve square roots and inverse trigonometry, so they are toleranced, once, here:
// a distance within kClearanceTolerance_m of the clearance counts as keeping it (touching is
// allowed, as the square inflation allows sliding along an obstacle).
#pragma once

#include <optional>
#include <utility>

#include "geometry/vec2.h"

namespace plantsim::geom {

inline constexpr double kClearanceTolerance_m = 1e-9;

/// Distance from p to the closed rectangle (0 inside).
double distance_to_rect(Vec2 p, const Rect& r);

/// Distance from the closed segment [p, q] to the closed rectangle (0 when they meet).
double segment_rect_distance(Vec2 p, Vec2 q, const Rect& r);

/// The part of the segment p + t (q - p), t in [0, 1], within distance d of the closed rectangle,
/// as its parameter interval {t0, t1} (a rectangle grown by a disk is convex, so the part is one
/// interval); nothing when no point of the segment is that close.
std::optional<std::pair<double, double>> segment_span_within(Vec2 p, Vec2 q, const Rect& r,
                                                             double d);

/// True when every point of the arc of the circle (center c, radius `radius`) from angle `from`
/// counter-clockwise through `sweep` (0 <= sweep <= 2 pi) is at least `clearance` from the
/// rectangle, up to the tolerance.
bool arc_keeps_clearance(Vec2 c, double radius, double from, double sweep, const Rect& r,
                         double clearance);

}  // namespace plantsim::geom
