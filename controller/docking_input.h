// What the docking stack knows at one control step, as the robot's side hands it over: the
// estimate and odometry, the charger's contacts and detection, what moves nearby, the bumper and
// the estimate's health. Shared by the docking phases and the collaborators they call.
#pragma once

#include <optional>
#include <vector>

#include "controller/collision_check.h"
#include "controller/diff_drive.h"
#include "controller/path_geometry.h"

namespace plantsim::controller {

struct DockingInput {
  Pose2 pose;                               ///< estimated pose in the map frame (localisation)
  Pose2 odom_pose;                          ///< pose in the continuous odometry frame
  double speed_mps = 0;                     ///< estimated forward speed
  double yaw_rate_radps = 0;                ///< the gyro's reading
  double dt_s = 0;                          ///< control period
  bool charger_contact = false;             ///< the charger's pads touch the robot's contacts
  bool charging = false;                    ///< the charger reports a good connection
  std::optional<Pose2> charger_in_robot;    ///< detected docked pose, robot frame, if seen
  std::vector<MovingBox> nearby_obstacles;  ///< sensed moving obstacles, map frame
  bool bumper_front = false;                ///< the bumper is pressed ahead of the axle ...
  bool bumper_rear = false;                 ///< ... or behind it
  bool displaced = false;       ///< moved without its wheels (shoved, slid) or touched something
  bool localized = true;        ///< the estimate is healthy and tight enough to plan from
  double position_sigma_m = 0;  ///< 1-sigma of the position estimate (largest direction)
};

}  // namespace plantsim::controller
