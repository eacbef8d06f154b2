// What one docking episode gives back (EpisodeResult), split by who reads it: the outcome
// (EpisodeOutcome: the status and failure, the metrics the referee measured from the truth) that
// records, gates and summaries read, and the log (EpisodeLog: trajectory, events, plan artefacts,
// perception snapshots) that figures, replays and animations draw.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "controller/docking.h"
#include "controller/local_controller.h"
#include "planner/planner.h"
#include "robot/failure.h"
#include "robot/perception.h"
#include "robot/travel.h"
#include "sim/integrity_watch.h"

namespace plantsim::episode {

using geom::Pose2;
using geom::Vec2;

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

/// How an episode ended. The records spell it as status_name() does.
enum class EpisodeStatus {
  kTimeout,              ///< out of time (until something ends the episode sooner)
  kDocked,               ///< charging, no collision, on estimates it could trust (success)
  kUndocked,             ///< ... and, with docking.undock, back at the staging pose (success)
  kDockedWithCollision,  ///< charging after a collision on the way
  kDockedOffEstimate,    ///< charging after driving on an estimate off without knowing
  kCaught,               ///< a moving target was reached (success)
  kFailed,               ///< the docking gave up (retries, relocalisation or approach time)
  kTrapped,              ///< potential-field travel could not leave a local minimum
  kInterrupted,          ///< stopped from outside (a signal) before it ended
  kPlannerAnswer,        ///< it went no further than the planner's answer (plan_status)
};

/// Not written to JSON as a number: records spell the status as status_name() does.
template <typename Json>
void to_json(Json&, EpisodeStatus) = delete;

/// What travel's end means for the episode (no collision or integrity breach yet considered).
EpisodeStatus status_of(robot::TravelEnd end);

/// The outcome: what records, gates and summaries read.
struct EpisodeOutcome {
  std::optional<robot::Failure>
      failure;  ///< why it did not succeed (set exactly when !succeeded())
  EpisodeStatus status = EpisodeStatus::kTimeout;
  planner::PlanStatus plan_status = planner::PlanStatus::kOk;  ///< with kPlannerAnswer
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
  std::string travel = "path";    ///< the travel mode's name (robot/travel_registry.h)
  std::string steered_by;         ///< an outside controller's name (EpisodeSteering), or empty
  int local_minima = 0;           ///< potential-field travel: local minima met
  int wall_follows = 0;           ///< ... and wall-following episodes begun
  planner::PlanStats plan_stats;  ///< of the first plan (build and query time, graph size)
  bool error_measured =
      false;            ///< position/heading errors were measured (at contact or at the end)
  Pose2 measured_pose;  ///< the true pose they were measured at
  std::string perception_mode = "sensors";
  double localization_error_max_m = 0;  ///< true against estimated position, worst over the episode
  std::string localization_status =
      "ok";                        ///< worst health the estimator reported: ok, degraded, lost
  sim::IntegrityRecord integrity;  ///< driving on a bad estimate (sim/integrity_watch.h)
  int relocalizations = 0;         ///< times the estimate restarted from a global scan match
  int unmapped_seen = 0;  ///< unmapped obstacles perception marked at some time (of the plant's)
  // Navigation-benchmark metrics over the travel to the staging pose, from the truth
  // (episode/navigation_metrics.h; docs/batch.md defines each); NaN where not measured.
  double min_clearance_m = NAN;           ///< true footprint to the nearest true obstacle, smallest
  double mean_clearance_m = NAN;          ///< ... its mean over the travel's control periods
  double near_obstacle_share = NAN;       ///< share of those periods closer than 0.3 m to one
  double rms_jerk_mps3 = NAN;             ///< RMS of the forward speed's second difference
  double rms_angular_accel_radps2 = NAN;  ///< RMS of the yaw rate's first difference
  // The local controller's wall time per step call (episode/controller_clock.h): not
  // deterministic, never compared between runs (kWallTimeFields, episode_json.h).
  std::int64_t controller_cycles = 0;  ///< its step calls
  double controller_ms_median = NAN;
  double controller_ms_p99 = NAN;
};

/// The status as the records spell it: "docked", "docked_with_collision", "docked_off_estimate",
/// "undocked", "caught", "failed", "trapped", "timeout", "interrupted", or the planner's answer
/// ("no path", "start blocked", ...; "ok" for a plan-only run).
std::string status_name(const EpisodeOutcome& outcome);

/// The log: what figures, replays and animations draw.
struct EpisodeLog {
  std::vector<Vec2> plan;         ///< the plan at the end (the last replan's, or the first)
  std::vector<Vec2> first_plan;   ///< the plan the robot set off on (path_length_m is its length)
  planner::PlanTrace plan_trace;  ///< what the planner did on its way (seed 003's walks, 002's)
  std::string plan_note;          ///< what the planner said about its plan
  std::vector<TrajectorySample> trajectory;
  std::vector<geom::Rect> moving_final;  ///< where the moving obstacles were at the end
  /// Where each moving obstacle was over time (every 0.25 s, as the physics moved it).
  struct MovingTrack {
    std::vector<double> t_s;
    std::vector<geom::Rect> boxes;
  };
  std::vector<MovingTrack> moving_tracks;
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
  /// What a local controller that samples trajectories (MPPI, DWB) weighed, about once a second
  /// while it drove: a few samples and its choice (controller_clock.h), for the replay.
  struct ControllerSketch {
    double t_s;
    controller::TrajectorySketch sketch;
  };
  std::vector<ControllerSketch> controller_sketches;
  /// How the logs were thinned to their limits (EpisodeConfig::log_limits): 1 and 0 when not.
  struct LogThinning {
    int trajectory_every = 1;  ///< control periods between the trajectory's samples at the end
    int moving_every = 1;      ///< moving tracks kept every this many 0.25 s
    int snapshots_every = 1;   ///< perception snapshots kept every this many scan_log_period_s
    int sketches_every = 1;    ///< controller sketches kept every this many seconds
    std::int64_t events_dropped = 0;
    bool any() const {
      return trajectory_every > 1 || moving_every > 1 || snapshots_every > 1 ||
             sketches_every > 1 || events_dropped > 0;
    }
  } thinning;
};

/// One episode's outcome and log together, as the loop fills them; a reader takes the part it
/// reads (records and gates the outcome, figures both).
struct EpisodeResult : EpisodeOutcome, EpisodeLog {};

}  // namespace plantsim::episode
