// Square and stepped inflation, rounded outward.
#include "planner/inflation.h"

#include <cmath>
#include <stdexcept>

namespace plantsim::planner {

Rect round_outward(const Rect& r) {
  const double k = 1.0 / kInflationLattice_m;  // scaling by a power of two is exact
  return {std::floor(r.xmin * k) / k, std::floor(r.ymin * k) / k, std::ceil(r.xmax * k) / k,
          std::ceil(r.ymax * k) / k};
}

std::vector<Rect> inflate(const std::vector<Rect>& raw, double clearance_m, int corner_steps) {
  if (corner_steps < 1) throw std::invalid_argument("corner_steps must be at least 1");
  std::vector<Rect> out;
  out.reserve(raw.size() * corner_steps);
  for (const Rect& r : raw) {
    if (clearance_m <= 0 || corner_steps == 1) {
      out.push_back(round_outward(r.inflated(std::max(clearance_m, 0.0))));
      continue;
    }
    // Step j covers the directions between angles j and j+1 of the corner's quarter circle:
    // a point there lies within (m cos(theta_j), m sin(theta_j+1)) of the corner.
    for (int j = 0; j < corner_steps; ++j) {
      const double a0 = 0.5 * M_PI * j / corner_steps, a1 = 0.5 * M_PI * (j + 1) / corner_steps;
      const double ex = clearance_m * std::cos(a0), ey = clearance_m * std::sin(a1);
      out.push_back(round_outward({r.xmin - ex, r.ymin - ey, r.xmax + ex, r.ymax + ey}));
    }
  }
  return out;
}

}  // namespace plantsim::planner
