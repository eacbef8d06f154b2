// The docking manoeuvre as a state machine: travel along the planned path to the staging
// pose, turn onto the charger's approach axis, approach slowly while steering onto the axis,
// and when the pads touch, hold them pressed until the charger says it is charging (docked),
// or back off to the staging pose and retry. The arc check and the bumper guard every phase:
// the approach and the back-off stop for what they sense (the charger itself excepted), and
// the bumper forbids pushing on into anything but the pads. Travel follows the plan in the map
// frame (localised pose); from the staging pose on, everything happens in the odometry frame, which
// never jumps: the dock is placed there from the map once, then re-anchored by every charger
// detection, which removes localisation error and odometry drift from the final approach.
// This file owns the phases; its collaborators, each with its own parameters, do the rest as
// Nav2's docking server and RPP split it: the path follower (path_follower.h), the collision
// checker (motion_guard.h), giving way to people (yield_policy.h) and the dock's pose filter
// (dock_pose_filter.h).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "controller/dock_pose_filter.h"
#include "controller/docking_input.h"
#include "controller/motion_guard.h"
#include "controller/path_follower.h"
#include "controller/pure_pursuit.h"
#include "controller/yield_policy.h"

namespace plantsim::controller {

enum class DockPhase { kTravel, kAlign, kApproach, kBackOff, kDocked, kUndock, kUndocked, kFailed };
std::string_view to_string(DockPhase p);

/// Why the manoeuvre ended in kFailed, as the robot itself knows it.
enum class DockFailure {
  kNone,
  kRetriesExhausted,  ///< the last allowed approach missed too
  kBlocked,           ///< the back-off stayed blocked past stuck_timeout_s
  kUnsettled,         ///< after a displacement it never settled (touching, displaced) within
                      ///< stuck_timeout_s
  kNotLocalized,      ///< ... because the estimate never became healthy and tight again
  kUndockBlocked,     ///< charging, but the way back to the staging pose stayed blocked
};
std::string_view to_string(DockFailure f);

struct DockingParams {
  double staging_distance_m = 1.0;     ///< staging pose this far behind the docked pose
  double approach_speed_mps = 0.08;    ///< final approach speed
  double approach_lookahead_m = 0.35;  ///< pure-pursuit carrot distance on the approach axis
  double align_tolerance_rad = 0.01;   ///< turn at staging until within this of the axis
  double align_speed_radps = 0.8;
  double backoff_speed_mps = 0.15;
  double overshoot_limit_m = 0.05;  ///< passing the dock this far without contact = miss
  int max_retries = 3;
  double approach_timeout_s = 40.0;  ///< an approach lasting longer counts as a miss
  double press_speed_mps = 0.02;     ///< creep into the pads while they are touched, until charging
  double press_timeout_s = 1.5;      ///< pressed this long without charging: a miss
  double stuck_timeout_s = 20.0;     ///< approach or back-off blocked (or unsettled after a shove)
                                     ///< this long: give up, stopped
  /// Lost this long after a displacement: give up (the robot searches meanwhile:
  /// robot/lost_search.h). Three minutes: in a 100 x 60 m yard a lone wall may be all a 20 m
  /// lidar sees, and at the search's 0.3 m/s the 90 s this was took 27 m, short of a wall's end
  /// (kidnapped particle-filter robots on the tuning yards that gave up mid-search).
  double relocalize_timeout_s = 180.0;
  bool undock = false;    ///< after charging starts, reverse to the staging pose (guarded)
  double settle_s = 1.0;  ///< after a displacement: stopped, localised and untouched this long
                          ///< before recovering (a new way to the staging pose)
  // The collaborators' own parameters (their keys stay in the configuration's "docking").
  MotionGuardParams guard;      ///< the arc check (footprint set from the world)
  PathFollowParams travel;      ///< travel to the staging pose
  YieldParams yield;            ///< giving way to people
  DockPoseFilterParams filter;  ///< the dock's pose from detections
};

/// What one control step did that the episode reports as an event (each one is also counted).
/// Reported by the part that did it: the docking controller, or the travel for a replan.
struct StepEvents {
  bool stopped = false;    ///< stopped for something in the way (a new encounter)
  bool retried = false;    ///< backed off to try the docking again
  bool recovered = false;  ///< settled and set off again after a displacement
  bool replanned = false;  ///< a new plan around what blocked the way
};

struct DockingCommand {
  Twist twist;
  DockPhase phase = DockPhase::kTravel;
  double cross_track_error_m = 0;  ///< while travelling
  bool blocked = false;            ///< stopped because the arc ahead is not clear
  bool replan_requested = false;   ///< blocked long enough: plan again around what is seen
  bool recover_requested = false;  ///< settled after a displacement: plan a new way to the staging
                                   ///< pose (the controller is travelling again; give it the path)
  StepEvents events;
};

class DockingController {
 public:
  /// Travels with `tracker` (the local controller) along `path`.
  DockingController(std::unique_ptr<LocalController> tracker, DockingParams docking,
                    std::vector<Vec2> path, Pose2 charger_on_map);
  /// ... with pure pursuit of these parameters.
  DockingController(PurePursuitParams tracking, DockingParams docking, std::vector<Vec2> path,
                    Pose2 charger_on_map);

  DockingCommand step(const DockingInput& in);

  DockPhase phase() const { return phase_; }
  /// Why the phase is kFailed (kNone otherwise).
  DockFailure failure() const { return failure_; }
  int retries() const { return retries_; }
  int stops() const { return guard_.stops(); }
  int recoveries() const { return recoveries_; }
  bool recovering() const { return recovering_; }
  /// The docked pose as the controller currently believes it, in the odometry frame.
  const Pose2& dock_estimate() const { return dock_.pose(); }
  /// Replaces the path still to travel (after a replan); only while travelling.
  void replace_path(std::vector<Vec2> path);

 private:
  DockingCommand step_phase(const DockingInput& in);
  DockingCommand decide(const DockingInput& in);
  /// Along the path to the staging pose (path_follower.h); there, the dock placed.
  DockingCommand travel(const DockingInput& in);
  /// Turning in place onto the dock's axis.
  DockingCommand align(const DockingInput& in);
  DockingCommand approach(const DockingInput& in);
  DockingCommand recover(const DockingInput& in);
  /// Backs straight away from a moving obstacle about to reach the robot, if the way back is
  /// clear; false when nothing threatens.
  bool yield(const DockingInput& in, DockingCommand& out);
  /// Where the dock estimate puts the docked pose, in the map frame.
  Pose2 dock_in_map(const DockingInput& in) const;
  /// Where the dock estimate puts the charger's block, in the map frame.
  Vec2 charger_in_map(const DockingInput& in) const;
  Vec2 in_dock_frame(Vec2 p) const;
  void miss();
  /// False (and the stop counted) when the arc of `twist` meets something sensed, leaving out
  /// what lies at the charger when `spare_charger`.
  bool guard(const DockingInput& in, const Twist& twist, bool spare_charger);
  void fail(DockFailure why);
  /// Backs straight out along the axis (guarded); true once at the staging pose.
  bool reverse_to_staging(const DockingInput& in, DockingCommand& out);

  PathFollower follower_;
  DockingParams params_;
  MotionGuard guard_;
  DockPoseFilter dock_;  // the dock in the odometry frame, refined by detections
  Pose2 dock_map_;       // the charger on the map
  DockPhase phase_ = DockPhase::kTravel;
  DockFailure failure_ = DockFailure::kNone;
  bool last_unsettled_by_localization_ = false;  // the last unsettled step was only the estimate's
  int retries_ = 0;
  bool giving_up_ = false;  // the last back-off before failing
  double approach_time_s_ = 0;
  double press_time_s_ = 0;  // holding the pads
  bool pressing_ = false;
  double stuck_time_s_ = 0;  // approach or back-off blocked
  bool recovering_ = false;  // stopped after a displacement, waiting to settle
  double settled_s_ = 0;
  double unsettled_s_ = 0;
  int recoveries_ = 0;
  double bystander_waited_s_ = 0;  // at the staging pose, over the episode
  StepEvents events_;              // of the step under way
};

}  // namespace plantsim::controller
