// Which directions around a point are already known to be blocked, as a union of open
// intervals of pseudo-angle: a cheap monotone stand-in for the angle (0 along +x, 1 along +y,
// 2 along -x, 3 along -y, period 4), with no trigonometry. Used only to stop a visibility
// search early and to rule out candidates, never to accept an edge, so it is made
// conservative: each interval is shrunk by kPseudoAngleSlack, far above the rounding of its
// endpoints (a few 1e-16), which can only delay a stop or keep a blocked candidate, never
// wrongly stop or drop a visible one.
#pragma once

#include <utility>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::planner {

inline constexpr double kPseudoAngleSlack = 1e-9;
inline constexpr double kPseudoAnglePeriod = 4.0;
/// Relative margin by which a point must lie beyond a rectangle's farthest corner before the
/// rectangle is said to hide it (distances are rounded to a few 1e-16 relative).
inline constexpr double kDepthSlack = 1e-9;

/// Pseudo-angle of direction d (d != 0), in [0, 4), increasing counter-clockwise.
inline double pseudo_angle(geom::Vec2 d) {
  if (d.y >= 0) return d.x >= 0 ? d.y / (d.x + d.y) : 1.0 - d.x / (d.y - d.x);
  return d.x < 0 ? 2.0 - d.y / (-d.x - d.y) : 3.0 + d.x / (d.x - d.y);
}

class AngleCoverage {
 public:
  /// Adds the open interval of directions from `lo` counter-clockwise to `hi` (pseudo-angles
  /// in [0, 4); hi < lo means it wraps through 0). It is shrunk by the slack.
  void add(double lo, double hi);
  /// True when every direction is covered.
  bool full() const;
  /// True when direction `a` (a pseudo-angle in [0, 4)) lies inside a covered interval. The
  /// intervals were shrunk by the slack, so a direction whose rounded pseudo-angle is inside
  /// is truly inside the open interval that was added.
  bool covers(double a) const;
  void clear() { intervals_.clear(); }

 private:
  void insert(double lo, double hi);
  std::vector<std::pair<double, double>> intervals_;  // sorted, disjoint, within [0, 4]
};

}  // namespace plantsim::planner
