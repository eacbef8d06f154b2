// The local controller: what follows the plan to the staging pose, step by step, whichever method
// it is (regulated pure pursuit, MPPI, DWB, or one a plugin adds). The path follower
// (path_follower.h) holds one and keeps what is not the method's: the uncertainty slow-down, the
// arc check that stops short of what moves ahead, backing out and replanning when blocked.
// A controller sees the estimate, its plan, the map it was built with and what the robot senses,
// never the simulator. Header-only: installed for plugins, with its value types.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "controller/diff_drive.h"
#include "controller/moving_box.h"
#include "geometry/vec2.h"
#include "util/component_info.h"

namespace plantsim::controller {

/// One step's command and what the path follower needs to know of it.
struct TrackingCommand {
  Twist twist;
  bool goal_reached = false;
  double cross_track_error_m = 0;      ///< distance from the path (estimated pose)
  double carrot_bearing_rad = 0;       ///< where the path ahead lies, robot frame (0: dead ahead);
                                       ///< the follower turns in place to it while blocked
  double straight_ahead_m = INFINITY;  ///< how far it drives on before it stops (the path's end or
                                       ///< a sharp corner, where it turns in place)
};

/// The facts of the robot and the plant a controller is built for (never its parameters).
struct LocalControllerContext {
  double footprint_radius_m = 0.2;  ///< the robot's disk
  double wheel_base_m = 0.4;
  double max_wheel_speed_mps = 1.0;  ///< the motors' limit at the rim
  double max_accel_mps2 = 1.0;       ///< the drive's acceleration limit
  double control_period_s = 1.0 / 30;
  std::vector<geom::Rect> map_obstacles;  ///< the robot's map: its boxes ...
  geom::Rect floor;                       ///< ... and the floor inside the walls
  std::uint64_t seed = 1;                 ///< for a controller that samples (the episode's)
};

/// One control step's question.
struct LocalQuery {
  geom::Pose2 pose;                                          ///< the estimate, map frame
  double speed_mps = 0;                                      ///< the estimated forward speed
  double yaw_rate_radps = 0;                                 ///< the gyro's
  double dt_s = 0;                                           ///< the control period
  const std::vector<MovingBox>* nearby_obstacles = nullptr;  ///< what it senses (may be null)
};

class LocalController {
 public:
  virtual ~LocalController() = default;
  /// A new plan to follow from wherever the robot is (the first, or after a replan).
  virtual void set_path(std::vector<geom::Vec2> path) = 0;
  /// One control step.
  virtual TrackingCommand step(const LocalQuery& q) = 0;

  /// Set by the plugin loader on a plugin's controller (empty for a built-in): whose it is, for
  /// the path follower to name when a call throws. The follower catches around its calls
  /// instead of a wrapper forwarding each one (a wrapper cost 10 to 15 ns a call, a tenth of a
  /// Stanley step: `plantsim bench plugins`).
  const std::string& plugin_origin() const { return plugin_origin_; }
  void set_plugin_origin(std::string who) { plugin_origin_ = std::move(who); }

 private:
  std::string plugin_origin_;
};

/// What a controller that samples trajectories weighed at its last step, in the map frame: a
/// few of its samples (spread over the batch, not the best ones) and the trajectory it chose
/// (MPPI's optimum, DWB's best scored). The replay draws them; nothing that decides reads them.
struct TrajectorySketch {
  std::vector<std::vector<geom::Vec2>> sampled;
  std::vector<geom::Vec2> chosen;
};

/// Implemented beside LocalController by a controller that samples trajectories (MPPI, DWB, or a
/// plugin's): a second base, so that the local controller's interface and a plugin's vtable stay
/// as they were. Asked once a second at most, after a step.
class SketchesTrajectories {
 public:
  virtual ~SketchesTrajectories() = default;
  /// At most `max_sampled` samples, each at most `max_points` points (first and last kept).
  virtual TrajectorySketch last_trajectories(int max_sampled, int max_points) const = 0;
};

/// `poses`' positions, at most `max_points` of them evenly spaced, first and last kept.
inline std::vector<geom::Vec2> sketch_points(const std::vector<geom::Pose2>& poses,
                                             int max_points) {
  std::vector<geom::Vec2> out;
  const std::size_t n = poses.size();
  if (n == 0 || max_points <= 0) return out;
  const std::size_t want =
      std::min<std::size_t>(n, static_cast<std::size_t>(std::max(2, max_points)));
  for (std::size_t k = 0; k < want; ++k) {
    const std::size_t i = want == 1 ? 0 : k * (n - 1) / (want - 1);
    out.push_back(poses[i].position());
  }
  return out;
}

/// A local controller's registry entry (local_controller_registry.h).
struct LocalControllerEntry : util::ComponentInfo {
  std::function<std::unique_ptr<LocalController>(const LocalControllerContext&,
                                                 const util::ParamValues&)>
      make;
};

}  // namespace plantsim::controller
