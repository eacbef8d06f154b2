// A sensed obstacle as the robot's side hands it to a controller: its box now and its velocity,
// both in the map frame. Header-only: installed for plugins.
#pragma once

#include "geometry/vec2.h"

namespace plantsim::controller {

struct MovingBox {
  geom::Rect box;
  geom::Vec2 velocity;
};

}  // namespace plantsim::controller
