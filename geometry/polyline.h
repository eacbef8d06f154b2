// Measures of polylines (paths as point sequences), shared by planners, controllers and tests.
#pragma once

#include <vector>

#include "geometry/vec2.h"

namespace plantsim::geom {

/// Sum of the segment lengths; 0 for fewer than two points.
inline double polyline_length(const std::vector<Vec2>& points) {
  double total = 0;
  for (std::size_t i = 1; i < points.size(); ++i) total += distance(points[i - 1], points[i]);
  return total;
}

}  // namespace plantsim::geom
