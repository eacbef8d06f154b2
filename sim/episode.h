// What one docking episode is asked to do (EpisodeConfig: the controllers', drive's, sensors'
// and docking's parameters, faults) and what it gives back (EpisodeResult: the metrics the
// referee measured from the truth, the trajectory log, events). The loop that runs it is
// episode/run_episode.h.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "controller/docking.h"
#include "controller/potential_field.h"
#include "controller/traction.h"
#include "planner/planner.h"
#include "robot/failure.h"
#include "robot/perception.h"
#include "robot/travel.h"
#include "sim/integrity_watch.h"
#include "sim/physics_world.h"
#include "sim/sensor_suite.h"  // the parameter structs of every sensor
#include "sim/wheel_drive.h"

namespace plantsim::sim {

/// The charger's pads: they report charging when pressed with the robot within these.
struct DockTolerance {
  double position_m = 0.02;  ///< robot centre off the approach axis
  double heading_rad = 2.0 * M_PI / 180.0;
  double dwell_s = 0.5;        ///< pressed within tolerance this long
  double min_press_m = 0.001;  ///< pads compressed at least this far
};

/// How the robot travels to the staging pose (or to a moving target): along the planner's
/// path by pure pursuit, or by seed 001's potential field with wall following (the planner's
/// path is then only the reference the result is measured against).
enum class TravelMode { kPath, kPotentialField };
inline std::string_view to_string(TravelMode m) {
  return m == TravelMode::kPath ? "path" : "potential-field";
}

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
  StepSettings step;
  DriveParams drive;
  OdometryNoise odometry;
  LocalizationParams localization;  ///< oracle mode's fixes (true pose plus noise)
  DetectionParams detection;
  LidarParams lidar;
  ImuParams imu;
  BeaconParams beacon;
  robot::PerceptionParams perception;  ///< mode, EKF and tracker
  controller::PurePursuitParams tracking;
  controller::DockingParams docking;
  controller::TractionParams traction;
  TravelMode travel = TravelMode::kPath;
  controller::PotentialFieldParams field;
  double catch_distance_m = 0.1;         ///< a moving target is caught this close (edge to edge)
  robot::LostSearchParams lost_search;   ///< path travel: driving to find a view while lost
  double pursuit_replan_period_s = 1.0;  ///< path travel: plan to the target's position this often
  DockTolerance tolerance;
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

struct TrajectorySample {
  double t_s;
  Pose2 truth;
  Pose2 estimate;               ///< map frame (localised)
  double position_sigma_m = 0;  ///< the estimate's 1-sigma (largest direction; 0 in oracle mode)
  double speed_mps;
  double cross_track_m;
  controller::DockPhase phase;
  bool wall_following = false;  ///< potential-field travel in its wall-following state
  Vec2 target;                  ///< where the moving target was (worlds with one)
  robot::LocalizationHealth health = robot::LocalizationHealth::kOk;  ///< what the estimator said
};

struct EpisodeResult {
  std::optional<robot::Failure>
      failure;          ///< why it did not succeed (set exactly when !succeeded())
  std::string status;   ///< "docked", "docked_with_collision", "docked_off_estimate" (charging
                        ///< after driving on an estimate off without knowing), "caught", "failed",
                        ///< "trapped", "timeout", or a planner status
  bool docked = false;  ///< charging, no collision and localisation integrity (success)
  bool caught = false;  ///< a moving target was reached
  bool succeeded() const { return docked || caught; }
  double position_error_m = 0;  ///< true centre to docked pose, at contact or at the end
  double heading_error_deg = 0;
  bool charging = false;  ///< the charger's own signal was seen (charging started)
  bool undocked = false;  ///< with docking.undock: back at the staging pose after charging
  int collisions = 0;     ///< separate contacts with obstacles or walls
  int collisions_robot_moving =
      0;  ///< ... of which the robot began by moving towards what it touched
  int retries = 0;
  int stops = 0;       ///< times the robot stopped for a moving obstacle
  int replans = 0;     ///< new plans made around what blocked the way
  int recoveries = 0;  ///< settled and set off again after being displaced (shoved, slid)
  int slips = 0;       ///< wheel slips perception saw (each slowed the robot down)
  double time_s = 0;
  std::int64_t physics_steps = 0;  ///< fixed steps simulated
  double wall_s = 0;               ///< wall-clock seconds run_episode took (not simulated time)
  double path_length_m = 0;        ///< planned, start to staging pose
  double driven_length_m = 0;      ///< ground truth
  double max_cross_track_m = 0;
  std::string planner;
  std::string travel = "path";    ///< to_string(TravelMode)
  std::string steered_by;         ///< an outside controller's name (EpisodeSteering), or empty
  int local_minima = 0;           ///< potential-field travel: local minima met
  int wall_follows = 0;           ///< ... and wall-following episodes begun
  planner::PlanStats plan_stats;  ///< of the first plan (build and query time, graph size)
  std::vector<Vec2> plan;         ///< the plan at the end (the last replan's, or the first)
  std::vector<Vec2> first_plan;   ///< the plan the robot set off on (path_length_m is its length)
  std::vector<Vec2> explored;  ///< the planner's exploration walk, if it made one (seed 003, 002)
  std::string explored_label = "explored";  ///< what the planner calls it ("raw walk")
  std::vector<std::vector<Vec2>>
      tried;  ///< walks it tried before its answer (seed 003's ring search)
  std::vector<planner::PlanMark> marks;  ///< its labels for figures (seed 003's junction letters)
  std::string plan_note;                 ///< what the planner said about its plan
  std::vector<TrajectorySample> trajectory;
  std::vector<geom::Rect> moving_final;  ///< where the moving obstacles were at the end
  /// Where each moving obstacle was over time (every 0.25 s, as the physics moved it).
  struct MovingTrack {
    std::vector<double> t_s;
    std::vector<geom::Rect> boxes;
  };
  std::vector<MovingTrack> moving_tracks;
  bool error_measured =
      false;            ///< position/heading errors were measured (at contact or at the end)
  Pose2 measured_pose;  ///< the true pose they were measured at
  std::string perception_mode = "sensors";
  double localization_error_max_m = 0;  ///< true against estimated position, worst over the episode
  std::string localization_status =
      "ok";                   ///< worst health the estimator reported: ok, degraded, lost
  IntegrityRecord integrity;  ///< driving on a bad estimate (sim/integrity_watch.h)
  int relocalizations = 0;    ///< times the estimate restarted from a global scan match
  int unmapped_seen = 0;  ///< unmapped obstacles perception marked at some time (of the plant's)
  robot::ScanView last_scan;  ///< the last scan as perception placed it
  /// What perception saw over time (every scan_log_period_s): the scan and the tracked boxes.
  struct PerceptionSnapshot {
    double t_s;
    robot::ScanView scan;
    std::vector<controller::MovingBox> tracked;
    std::vector<geom::Rect> layer;
  };
  std::vector<PerceptionSnapshot> perception_log;
  std::vector<controller::MovingBox> tracked_final;  ///< obstacles perception tracked at the end
  std::vector<geom::Rect> layer_final;               ///< the local obstacle layer at the end
  /// Where the robot stopped for something, replanned, recovered after a displacement, backed
  /// off to retry the docking, began a collision, or failed (failure's time and place).
  struct Event {
    enum class Kind { kStop, kReplan, kRecovery, kCollision, kRetry, kFailure };
    Kind kind;
    double t_s;
    Vec2 at;  ///< true position (for a collision, the robot's centre when contact began)
  };
  std::vector<Event> events;
  /// A fault carried the robot off by hand (a kidnap): the truth's path is driven in legs
  /// between carries, and the carry is not driven length.
  struct Carry {
    double t_s;
    Pose2 from;
    Pose2 to;
  };
  std::vector<Carry> carries;
  /// How the logs were thinned to their limits (EpisodeConfig::log_limits): 1 and 0 when not.
  struct LogThinning {
    int trajectory_every = 1;  ///< control periods between the trajectory's samples at the end
    int moving_every = 1;      ///< moving tracks kept every this many 0.25 s
    int snapshots_every = 1;   ///< perception snapshots kept every this many scan_log_period_s
    std::int64_t events_dropped = 0;
    bool any() const {
      return trajectory_every > 1 || moving_every > 1 || snapshots_every > 1 || events_dropped > 0;
    }
  } thinning;
};

}  // namespace plantsim::sim
