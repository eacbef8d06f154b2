// One frame of the plant at an instant: the map, the path driven so far (by speed), the plan,
// what perception saw (scan, local layer, tracked boxes), the moving obstacles, the charger and
// the robot, with a legend and the clock. Drawn for the animation's frames and for the Python
// environment's render() (an RGB array), from whatever the caller holds at that instant.
#pragma once

#include <string>
#include <vector>

#include "controller/moving_box.h"
#include "episode/episode_result.h"
#include "render/image.h"
#include "robot/perception.h"
#include "worlds/world.h"

namespace plantsim::render {

struct PlantInstant {
  double t_s = 0;
  geom::Pose2 robot;  ///< where the robot is (the truth)
  std::string phase;  ///< travel, docking, ...
  const std::vector<episode::TrajectorySample>* trajectory = nullptr;   ///< driven so far
  std::size_t driven = 0;                                               ///< samples of it drawn
  const std::vector<episode::EpisodeResult::Carry>* carries = nullptr;  ///< its kidnaps
  std::vector<geom::Vec2> plan;
  const robot::ScanView* scan = nullptr;  ///< what perception placed, if any
  std::vector<geom::Rect> layer;
  std::vector<controller::MovingBox> tracked;
  std::vector<geom::Rect> moving;  ///< the moving obstacles where they are
};

/// The frame, `width_px` x `height_px` (RGBA), anti-aliased as every figure.
Image plant_frame(const worlds::World& world, const PlantInstant& at, int width_px, int height_px);

}  // namespace plantsim::render
