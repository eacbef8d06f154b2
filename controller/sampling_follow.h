// What a sampling controller (MPPI, DWB) reports besides its command, in the form the path
// follower reads it: progress along the plan (never back), distance from it, the bearing of the
// plan ahead, the goal it steers to, and the local distance field it scores against, built from
// the map the controller was given and what the robot senses this step.
#pragma once

#include <vector>

#include "controller/clearance_grid.h"
#include "controller/local_controller.h"
#include "controller/path_geometry.h"

namespace plantsim::controller {

class PathProgress {
 public:
  PathProgress() = default;
  explicit PathProgress(std::vector<Vec2> path);

  /// Moves on to the plan's point nearest `pose`, and fills the command's cross-track error,
  /// carrot bearing (`carrot_m` ahead) and goal_reached (within `goal_tolerance_m` of the end).
  void update(const Pose2& pose, double carrot_m, double goal_tolerance_m, TrackingCommand& out);
  /// The plan's end, facing along its last segment.
  Pose2 goal() const;
  const std::vector<Vec2>& path() const { return path_; }

 private:
  std::vector<Vec2> path_;
  std::size_t segment_ = 0;
};

/// How far from the robot's centre obstacles matter to critics that look `inflation_m` beyond
/// its footprint: the field's reach, two cells more so that interpolating near it stays exact.
inline double field_reach(double footprint_radius_m, double inflation_m) {
  return footprint_radius_m + inflation_m + 0.1;
}

/// The distance field of `half_side_m` around the robot (cells of `cell_m`, distances up to
/// `reach_m`): the map's boxes near it and the sensed ones.
ClearanceGrid local_clearance(const LocalControllerContext& ctx, const LocalQuery& q,
                              double half_side_m, double cell_m, double reach_m = INFINITY);

/// A sampling method as a local controller: progress on the plan, the goal and the local field
/// (a 6 m window in 5 cm cells) are this adapter's; the method only samples the command.
class SamplingController : public LocalController {
 public:
  /// `field_reach_m`: the furthest from the robot's centre an obstacle's distance matters to
  /// the method's critics (its footprint plus its inflation).
  SamplingController(const LocalControllerContext& ctx, double goal_tolerance_m,
                     double field_reach_m)
      : ctx_(ctx), goal_tolerance_m_(goal_tolerance_m), field_reach_m_(field_reach_m) {}

  void set_path(std::vector<Vec2> path) final;
  TrackingCommand step(const LocalQuery& q) final;

 protected:
  virtual void set_method_path(const std::vector<Vec2>& path) = 0;
  /// The command to drive now, from the field and the plan's end.
  virtual Twist sample(const LocalQuery& q, const ClearanceGrid& field, const Pose2& goal) = 0;
  const LocalControllerContext& context() const { return ctx_; }

 private:
  LocalControllerContext ctx_;
  double goal_tolerance_m_;
  double field_reach_m_;
  PathProgress progress_;
};

}  // namespace plantsim::controller
