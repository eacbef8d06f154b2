// A scripted obstacle (or the moving target) as it is at one instant: its box and velocity.
#pragma once

#include "geometry/vec2.h"

namespace plantsim::sim {

struct ActorState {
  geom::Rect box;
  geom::Vec2 velocity;  ///< world frame
};

}  // namespace plantsim::sim
