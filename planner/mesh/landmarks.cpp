// Landmarks: the farthest-point choice, the table filled in place.
#include "planner/mesh/landmarks.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plantsim::planner {

LandmarkTable measure_landmarks(
    int count, std::size_t points, std::size_t first,
    const std::function<std::vector<double>(std::size_t)>& distances_from,
    const std::function<bool(std::size_t)>& unusable) {
  LandmarkTable out;
  if (points == 0 || count <= 0) return out;
  // Filled landmark by landmark in place (`count` wide), then closed up if fewer were found: no
  // second copy of the table is ever held.
  out.distance.assign(points * count, std::numeric_limits<double>::quiet_NaN());
  std::vector<double> nearest(points, std::numeric_limits<double>::infinity());
  std::size_t next = first;
  while (out.landmarks < count) {
    const std::vector<double> from = distances_from(next);
    // The next landmark: the reachable point farthest from every landmark so far.
    double far = 0;
    for (std::size_t i = 0; i < points; ++i) {
      if (std::isfinite(from[i]) && !unusable(i)) out.distance[i * count + out.landmarks] = from[i];
      nearest[i] = std::min(nearest[i], from[i]);
      if (std::isfinite(nearest[i]) && nearest[i] > far) far = nearest[i], next = i;
    }
    ++out.landmarks;
    if (far == 0) break;
  }
  for (std::size_t i = 0; i < points; ++i)
    for (int k = 0; k < out.landmarks; ++k)
      out.distance[i * out.landmarks + k] = out.distance[i * count + k];
  out.distance.resize(points * out.landmarks);
  return out;
}

}  // namespace plantsim::planner
