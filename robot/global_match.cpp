// The beam-by-beam agreement of a scan with the map from a pose.
#include "robot/global_match.h"

#include <cmath>
#include <vector>

namespace plantsim::robot {

// Fewer beams than this that can confirm or contradict a pose (a mapped surface in range):
// no judgement either way.
constexpr int kMinJudgingBeams = 10;

std::optional<double> scan_agreement(const MapRaycaster& map, const LidarScan& scan,
                                     const geom::Pose2& pose, double tolerance_m,
                                     std::vector<double>* residuals) {
  const geom::Pose2 sensor = geom::compose(pose, scan.mount);
  const std::size_t n = scan.ranges.size(), stride = std::max<std::size_t>(1, n / 90);
  // The judged beams cast as one fan (the boxes in reach visited once, not once a beam); each
  // direction as cast() takes it from its angle, so each hit is the one cast() finds.
  thread_local std::vector<geom::Vec2> directions;
  thread_local std::vector<std::optional<RayHit>> hits;
  directions.clear();
  for (std::size_t i = 0; i < n; i += stride)
    directions.push_back(geom::unit_from_angle(sensor.yaw + scan.angle(i)));
  map.cast_fan(sensor.position(), directions, sensor.yaw + scan.angle(0),
               static_cast<double>(stride) * scan.angle_increment_rad, scan.max_range_m, hits);
  int agree = 0, beams = 0;
  for (std::size_t i = 0, k = 0; i < n; i += stride, ++k) {
    if (std::isnan(scan.ranges[i])) continue;  // a dropout says nothing
    const std::optional<RayHit>& hit = hits[k];
    // A return short of the mapped surface, or where the map has none in range, may be
    // something the map lacks (a box, a person): it neither confirms nor contradicts the pose.
    // Only a beam that passes where the map has a surface contradicts it. (Counted against the
    // pose, a box the map lacks in an open yard turned a right estimate into a lost one as the
    // robot came up to it.)
    if (scan.valid(i) && (!hit || scan.ranges[i] < hit->range_m - tolerance_m)) continue;
    // A surface the map puts at the edge of the lidar's range may read as a return or as none
    // with a few centimetres of error in the pose: such a beam judges nothing. (On open ground
    // most of the map in range is a far wall at that edge: counted, a pose off by half a metre
    // would turn dozens of beams from "nothing in range" to "a wall", or back.)
    if (hit && hit->range_m > scan.max_range_m - tolerance_m) continue;
    // No return where the map has nothing in range agrees with every pose on open ground: it
    // judges nothing. (Counted, an estimate metres off in a yard read 95 % "agreement".)
    if (!scan.valid(i) && !hit) continue;
    ++beams;
    const bool agrees = scan.valid(i) && std::fabs(scan.ranges[i] - hit->range_m) <= tolerance_m;
    agree += agrees;
    if (agrees && residuals) residuals->push_back(scan.ranges[i] - hit->range_m);
  }
  if (beams < kMinJudgingBeams) return std::nullopt;
  return static_cast<double>(agree) / beams;
}

int valid_returns(const LidarScan& scan) {
  int returns = 0;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) returns += scan.valid(i);
  return returns;
}

}  // namespace plantsim::robot
