// The stopping speed: the positive root of the reaction-and-braking quadratic.
#include "controller/stopping_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plantsim::controller {

double stopping_speed_mps(double free_m, double decel_mps2, double reaction_s, double margin_m) {
  if (std::isinf(free_m) && free_m > 0) return std::numeric_limits<double>::infinity();
  const double room = std::max(0.0, free_m - margin_m);
  if (room <= 0 || decel_mps2 <= 0) return 0.0;
  // v t + v^2 / (2a) = room  <=>  v^2 + 2 a t v - 2 a room = 0.
  const double at = decel_mps2 * std::max(0.0, reaction_s);
  return -at + std::sqrt(at * at + 2.0 * decel_mps2 * room);
}

double stopping_distance_m(double v_mps, double decel_mps2, double reaction_s) {
  const double v = std::fabs(v_mps);
  if (decel_mps2 <= 0) return v > 0 ? std::numeric_limits<double>::infinity() : 0.0;
  return v * std::max(0.0, reaction_s) + v * v / (2.0 * decel_mps2);
}

}  // namespace plantsim::controller
