// The docking manoeuvre as a state machine: travel along the planned path to the staging
// pose, turn onto the charger's approach axis, approach slowly while steering onto the axis,
// and when the pads touch, hold them pressed until the charger says it is charging (docked),
// or back off to the staging pose and retry. The arc check and the bumper guard every phase:
// the approach and the back-off stop for what they sense (the charger itself excepted), and
// the bumper forbids pushing on into anything but the pads. Travel follows the plan in the map
// frame (localised pose); from the staging pose on, everything happens in the odometry frame, which
// never jumps: the dock is placed there from the map once, then re-anchored by every charger
// detection, which removes localisation error and odometry drift from the final approach.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "controller/collision_check.h"
#include "controller/pure_pursuit.h"

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
  double detection_blend = 0.3;   ///< weight of each new detection in the dock estimate
  double detection_gate_m = 0.1;  ///< a detection further than this from the dock estimate is
                                  ///< used only when the one before it agrees (outliers are single)
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
  // Moving obstacles met while travelling.
  double footprint_radius_m = 0.2;  ///< robot disk, for the arc check (set from the world)
  double safety_margin_m = 0.15;    ///< extra clearance the arc must keep
  double max_decel_mps2 = 1.0;      ///< braking, to size the arc checked ahead
  double check_extra_m = 0.4;       ///< checked beyond the braking distance
  double replan_after_s = 3.0;      ///< blocked this long: ask for a new plan
  double yield_horizon_s = 3.0;     ///< something reaching the robot this soon: back away
  double yield_speed_mps = 0.6;     ///< reversing speed when backing away
  // Someone standing beside the final approach may step into it (a blind walker gives the
  // robot under a second there): aligned at the staging pose, the robot waits for them to go.
  double bystander_reach_m = 1.5;     ///< standing this close to the approach's corridor
  double bystander_max_size_m = 1.0;  ///< ... and no larger (a fixture, not a person)
  double bystander_wait_s = 60.0;     ///< at most this long per episode, then it docks anyway
  // Travel slows as the estimate grows uncertain, instead of stopping.
  double confident_sigma_m = 0.05;  ///< full speed up to this 1-sigma of the position estimate
  double uncertain_sigma_m =
      0.5;  ///< ... slowed linearly to uncertain_speed_fraction at this and beyond
  double uncertain_speed_fraction = 0.6;
};

/// The share of travel speed an estimate of this 1-sigma allows (1 when confident).
double uncertainty_speed_fraction(const DockingParams& p, double position_sigma_m);

/// What the robot knows at one control step.
struct DockingInput {
  Pose2 pose;                               ///< estimated pose in the map frame (localisation)
  Pose2 odom_pose;                          ///< pose in the continuous odometry frame
  double speed_mps = 0;                     ///< estimated forward speed
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
  DockingController(PurePursuitParams tracking, DockingParams docking, std::vector<Vec2> path,
                    Pose2 charger_on_map);

  DockingCommand step(const DockingInput& in);

  DockPhase phase() const { return phase_; }
  /// Why the phase is kFailed (kNone otherwise).
  DockFailure failure() const { return failure_; }
  int retries() const { return retries_; }
  int stops() const { return stops_; }
  int recoveries() const { return recoveries_; }
  bool recovering() const { return recovering_; }
  /// The docked pose as the controller currently believes it, in the odometry frame.
  const Pose2& dock_estimate() const { return dock_odom_; }
  /// Replaces the path still to travel (after a replan); only while travelling.
  void replace_path(std::vector<Vec2> path);

 private:
  DockingCommand step_phase(const DockingInput& in);
  DockingCommand decide(const DockingInput& in);
  /// Along the path by pure pursuit, stopping short of what moves into the arc ahead.
  DockingCommand travel(const DockingInput& in);
  /// Stopped for something in the way: back out of a threat, or face the carrot; a replan asked
  /// for when it lasts.
  void hold_blocked(const DockingInput& in, const TrackingCommand& t, DockingCommand& out);
  /// Turning in place onto the dock's axis.
  DockingCommand align(const DockingInput& in);
  DockingCommand approach(const DockingInput& in);
  DockingCommand recover(const DockingInput& in);
  /// Backs straight away from a moving obstacle about to reach the robot, if the way back is
  /// clear; false when nothing threatens.
  bool yield(const DockingInput& in, DockingCommand& out);
  /// Something person-sized stands near the corridor the approach will sweep, the charger's
  /// own block left out.
  bool bystander_near_approach(const DockingInput& in) const;
  /// Where the dock estimate puts the charger's block, in the map frame.
  Vec2 charger_in_map(const DockingInput& in) const;
  Vec2 in_dock_frame(Vec2 p) const;
  void miss();
  void use_detection(const Pose2& seen_in_odom);
  /// False (and the stop counted) when the arc of `twist` meets something sensed, leaving out
  /// what lies at the charger when `spare_charger`.
  bool guard(const DockingInput& in, const Twist& twist, bool spare_charger);
  void note_clear(double dt_s);
  /// A block met: counted (and reported) as a stop unless it follows the last one closely.
  void note_blocked();
  void fail(DockFailure why);
  /// Backs straight out along the axis (guarded); true once at the staging pose.
  bool reverse_to_staging(const DockingInput& in, DockingCommand& out);

  PurePursuit tracker_;
  DockingParams params_;
  Pose2 dock_map_;   // the charger on the map
  Pose2 dock_odom_;  // the same in the odometry frame, refined by detections
  bool dock_placed_ = false;
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
  double blocked_time_s_ = 0;
  bool was_blocked_ = false;
  double clear_time_s_ = 1e9;  // driven unblocked since the last block
  double straight_run_m_ =
      0;  // driven straight ahead since the last turn: known free to reverse into
  int stops_ = 0;
  double bystander_waited_s_ = 0;            // at the staging pose, over the episode
  std::optional<Pose2> rejected_detection_;  // the last detection the gate held back
  StepEvents events_;                        // of the step under way
};

}  // namespace plantsim::controller
