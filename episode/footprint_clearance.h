// The clearance the referee measures (episode/navigation_metrics.h): how far the robot's true
// footprint (its disk, or its rectangle at its heading) is from the nearest true obstacle of the
// plant: a static box, mapped or not, a wall (the floor's boundary) or a moving obstacle (a
// person, a cart). The charger's block is not counted: docking touches it by design.
#pragma once

#include <vector>

#include "geometry/vec2.h"
#include "worlds/world.h"

namespace plantsim::episode {

/// The plant's static boxes (mapped and unmapped) and floor, gathered once per episode.
class FootprintClearance {
 public:
  explicit FootprintClearance(const worlds::World& plant);
  /// Distance from the footprint at `pose` to the nearest static box, wall or box of `moving`;
  /// 0 when it touches or overlaps one.
  double at(const geom::Pose2& pose, const std::vector<geom::Rect>& moving) const;

 private:
  /// Distance from the footprint to one box, or at least `best` when it cannot beat it.
  double to_box(const geom::Pose2& pose, const geom::Rect& box, double best) const;
  double to_walls(const geom::Pose2& pose) const;

  worlds::RobotSpec robot_;
  geom::Rect floor_;
  std::vector<geom::Rect> boxes_;
};

}  // namespace plantsim::episode
