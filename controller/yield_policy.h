// When the docking stack gives way to people: backing away from something moving that will reach
// the robot within a horizon, and waiting at the staging pose while someone person-sized stands
// beside the corridor the final approach will sweep (a walker there gives the robot under a
// second once it is on its way). Decisions only; the docking phases act on them.
#pragma once

#include <vector>

#include "controller/collision_check.h"

namespace plantsim::controller {

struct YieldParams {
  double yield_horizon_s = 3.0;  ///< something reaching the robot this soon: back away
  double yield_speed_mps = 0.6;  ///< reversing speed when backing away
  // Someone standing beside the final approach may step into it: aligned at the staging pose,
  // the robot waits for them to go.
  double bystander_reach_m = 1.5;     ///< standing this close to the approach's corridor
  double bystander_max_size_m = 1.0;  ///< ... and no larger (a fixture, not a person)
  double bystander_wait_s = 60.0;     ///< at most this long per episode, then it docks anyway
};

/// Some box (moving on at its velocity) comes within `radius_m` of `position` within the
/// horizon.
bool threatened(const YieldParams& p, geom::Vec2 position, double radius_m,
                const std::vector<MovingBox>& boxes);

/// The same, counting only what moves faster than a standing person sways (0.2 m/s).
bool threatened_by_movers(const YieldParams& p, geom::Vec2 position, double radius_m,
                          const std::vector<MovingBox>& boxes);

/// Something person-sized stands within `clearance_m` + bystander_reach_m of the corridor from
/// `from` to `to`, the block at `charger_at` (the charger itself) left out.
bool bystander_near_corridor(const YieldParams& p, geom::Vec2 from, geom::Vec2 to,
                             geom::Vec2 charger_at, double clearance_m,
                             const std::vector<MovingBox>& boxes);

}  // namespace plantsim::controller
