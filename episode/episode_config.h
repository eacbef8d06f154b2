// What one docking episode is asked to do: the controllers', drive's, sensors' and docking's
// parameters and the faults (EpisodeConfig). Each part is the struct of the module that owns it;
// the episode only assembles them. What it gives back is episode_result.h; the loop that runs it
// is run_episode.h.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "controller/docking.h"
#include "controller/potential_field.h"
#include "controller/traction.h"
#include "robot/coastal_route.h"
#include "robot/lost_search.h"
#include "robot/perception.h"
#include "sim/physics_world.h"
#include "sim/sensor_suite.h"  // the parameter structs of every sensor
#include "sim/wheel_drive.h"
#include "util/param_spec.h"

namespace plantsim::episode {

/// A kidnap: at `at_s` the robot is lifted and set down moved by (dx, dy) and turned by dyaw
/// (in the world frame), at rest; nothing it senses says so but the scans that follow. Off
/// while at_s < 0. With distance_max_m > 0 the landing is drawn instead (sim/kidnap_landing.h):
/// distance_min_m to distance_max_m away, any heading, on free floor, from the episode's seed.
struct KidnapFault {
  double at_s = -1;
  double dx_m = 0, dy_m = 0, dyaw_rad = 0;
  double distance_min_m = 0, distance_max_m = 0;
  bool enabled() const { return at_s >= 0; }
  bool drawn() const { return distance_max_m > 0; }
};

/// Physics steps one episode may ask for (timeout_s / step.dt_s): 5,000,000 is 23 hours of
/// simulated time at 60 Hz, about two minutes of computing at this machine's 50,000 steps/s.
inline constexpr std::int64_t kMaxEpisodeSteps = 5000000;

struct EpisodeConfig {
  sim::StepSettings step;
  sim::DriveParams drive;
  sim::OdometryNoise odometry;
  sim::LocalizationParams localization;  ///< oracle mode's fixes (true pose plus noise)
  sim::DetectionParams detection;
  sim::LidarParams lidar;
  sim::ImuParams imu;
  sim::BeaconParams beacon;
  robot::PerceptionParams perception;  ///< mode, EKF and tracker
  controller::PurePursuitParams tracking;
  /// The local controller that follows the plan, by its registry name
  /// (controller/local_controller_registry.h); pure pursuit's parameters are `tracking`.
  std::string local_controller = "pure-pursuit";
  /// The parameters of registered components that have no struct here (MPPI's, DWB's, a
  /// plugin's), by "section.name"; a parameter not set has its declared default.
  util::NamedValues component_params;
  controller::DockingParams docking;
  controller::TractionParams traction;
  /// How the robot travels, by its registry name (robot/travel_registry.h): "path" or
  /// "potential-field" (seed 001; its parameters are `field`).
  std::string travel = "path";
  controller::PotentialFieldParams field;
  double catch_distance_m = 0.1;         ///< a moving target is caught this close (edge to edge)
  robot::LostSearchParams lost_search;   ///< path travel: driving to find a view while lost
  robot::CoastalParams coastal;          ///< path travel, sensors: routes keeping surfaces in sight
  double pursuit_replan_period_s = 1.0;  ///< path travel: plan to the target's position this often
  /// What the charger's pads accept as docked ("tolerance.*"); their travel and width are the
  /// plant's charger's, set when the episode starts.
  sim::ChargerPadParams tolerance;
  KidnapFault kidnap;
  double timeout_s = 600.0;
  int control_period_steps = 2;  ///< sensing, control and logging every this many steps (30 Hz)
  double scan_log_period_s =
      0;  ///< keep the scan and the tracks this often, for animations (0: only the last)
  /// The logs' sizes whatever the episode's duration (docs/config.md "Long episodes"): a log
  /// that reaches its limit keeps every other entry and is written half as often from then on,
  /// so that it still spans the whole episode; events past their limit are counted, not kept.
  struct LogLimits {
    std::size_t trajectory = 100000;    ///< samples (about 11 MB; 55 min at 30 Hz unthinned)
    std::size_t moving_boxes = 200000;  ///< all moving obstacles' track samples together
    std::size_t snapshots = 2000;       ///< perception snapshots (scan_log_period_s)
    std::size_t events = 20000;         ///< stops, replans, recoveries, retries
  } log_limits;
  std::uint64_t seed = 1;
};

}  // namespace plantsim::episode
