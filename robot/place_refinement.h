// A place for a scan refined on the likelihood field: the pose, near a match's answer, that
// brings the scan's returns closest to the mapped surfaces (a robust least-squares fit by
// pattern search). A correlative match's grid leaves its answer a cell or a rotation step off,
// which moves a return 20 m away by 20 cm: enough for a ray-cast check of the right place to
// reject it. Robot side: the map and the scan only.
#pragma once

#include <vector>

#include "geometry/vec2.h"
#include "robot/likelihood_field.h"

namespace plantsim::robot {

/// The pose within about `reach_m` and `reach_rad` of `start` minimising the sum over `points`
/// (robot frame) of min(d^2, cap_m^2), d the field's distance of the return from a surface.
geom::Pose2 refine_on_field(const LikelihoodField& field, const std::vector<geom::Vec2>& points,
                            geom::Pose2 start, double reach_m = 0.2, double reach_rad = 0.03,
                            double cap_m = 0.3);

}  // namespace plantsim::robot
