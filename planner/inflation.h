// Growing raw obstacle rectangles by the robot's clearance. Square corners are the source
// document's method; `corner_steps` > 1 replaces each square corner by a staircase of that many
// rectangles that still contains the exact rounded inflation (the Minkowski sum with a disk),
// a tighter and still safe obstacle. Every inflated coordinate is rounded outward to a lattice
// of kInflationLattice_m, so that obstacles meant to touch after inflation (two rectangles
// exactly 2 x clearance apart) do touch or overlap instead of leaving a gap of a few 1e-16 m
// that only floating-point rounding opened.
#pragma once

#include <vector>

#include "geometry/vec2.h"

namespace plantsim::planner {

using geom::Rect;

inline constexpr double kInflationLattice_m = 0x1p-30;  // about 0.93 nanometres

/// Rounds r outward to the inflation lattice (never shrinks it).
Rect round_outward(const Rect& r);

/// Inflated rectangles (corner_steps >= 1; 1 gives square corners).
std::vector<Rect> inflate(const std::vector<Rect>& raw, double clearance_m, int corner_steps = 1);

}  // namespace plantsim::planner
