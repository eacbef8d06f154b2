// Will the commanded motion hit something? The arc the robot would drive under a constant
// twist is sampled ahead over a given distance, and at each sample the disk footprint (plus a
// margin) is tested against every sensed box moved on by its velocity to the time the robot
// would be there. Pure geometry, no physics.
#pragma once

#include <vector>

#include "controller/diff_drive.h"
#include "controller/moving_box.h"
#include "geometry/vec2.h"

namespace plantsim::controller {

/// Distance from point p to the closed box r (0 inside).
double distance_to_box(geom::Vec2 p, const geom::Rect& r);

/// Distance from the segment ab to the closed box r (0 when they meet).
double segment_distance_to_box(geom::Vec2 a, geom::Vec2 b, const geom::Rect& r);

/// True when the disk of `radius_m` stays clear of every box along the arc of `twist` from
/// `pose` over `distance_m` of travel (sampled every `step_m`), the robot reaching each sample
/// at `travel_speed_mps` and each box moving on at its velocity (for at most `horizon_s`).
/// A twist with no forward motion checks the current position only. A box already closer
/// than `radius_m` only forbids coming closer still (so the robot can move away from it).
bool arc_clear(const geom::Pose2& pose, Twist twist, double travel_speed_mps, double distance_m,
               double radius_m, const std::vector<MovingBox>& boxes, double horizon_s = 3.0,
               double step_m = 0.05);

/// True when some box, moving on at its velocity, comes within `radius_m` of `position` in
/// the next `horizon_s` seconds (sampled every `step_s`).
bool position_threatened(geom::Vec2 position, double radius_m, const std::vector<MovingBox>& boxes,
                         double horizon_s, double step_s = 0.1);

}  // namespace plantsim::controller
