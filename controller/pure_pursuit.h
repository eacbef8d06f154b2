// Regulated pure pursuit: follows a polyline from the robot's estimated pose. The lookahead
// grows with speed between a minimum and a maximum; speed is reduced on tight curvature and
// near the path's end; the robot turns in place when the carrot is far off its heading.
// Pose in the world (odometry) frame; the carrot is expressed in the robot frame.
#pragma once

#include <vector>

#include "controller/diff_drive.h"
#include "controller/local_controller.h"
#include "controller/path_geometry.h"

namespace plantsim::controller {

struct PurePursuitParams {
  double lookahead_min_m = 0.25;
  double lookahead_max_m = 0.9;
  double lookahead_time_s = 1.2;  ///< lookahead = speed * this, clamped
  double sharp_turn_rad = 0.5;    ///< the carrot stops at a vertex turning more than this ...
  double corner_release_m = 0.1;  ///< ... until the robot is this close to it
  double max_linear_speed_mps = 0.6;
  double max_angular_speed_radps = 1.5;
  double min_approach_speed_mps = 0.05;        ///< floor of the goal slow-down
  double approach_slowdown_distance_m = 0.8;   ///< start slowing this far from the end
  double regulated_min_radius_m = 0.9;         ///< slow down below this turning radius
  double rotate_in_place_threshold_rad = 0.7;  ///< turn in place above this heading error ...
  double rotate_in_place_exit_rad = 0.1;       ///< ... until it is below this (no bulging arcs)
  double rotate_in_place_speed_radps = 1.0;
  double goal_tolerance_m = 0.03;  ///< done within this of the end
  double progress_window_m = 2.0;  ///< how far ahead the closest-point search looks
};

class PurePursuit {
 public:
  PurePursuit(PurePursuitParams params, std::vector<Vec2> path);

  /// One control step from the estimated pose and the current forward speed.
  TrackingCommand step(const Pose2& pose, double current_speed_mps);

  const std::vector<Vec2>& path() const { return path_; }
  const PurePursuitParams& params() const { return params_; }

 private:
  PurePursuitParams params_;
  std::vector<Vec2> path_;
  std::vector<double> to_end_;  // path length from each vertex to the end
  std::size_t segment_ = 0;     // progress: never moves back
  bool rotating_ = false;       // turning in place, until aligned
};

}  // namespace plantsim::controller
