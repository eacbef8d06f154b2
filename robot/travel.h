// How the robot gets to the charger (or to a moving target), behind one small interface: each
// control step it receives the perception, never the simulator's truth, and returns the twist
// to drive with its phase. Path travel follows the plan by pure pursuit and docks; field
// travel is seed 001's potential field, then docks; pursuit chases a moving target along
// plans made again every period.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "controller/docking.h"
#include "controller/local_controller.h"
#include "controller/potential_field.h"
#include "planner/planner.h"
#include "robot/coastal_route.h"
#include "robot/failure.h"
#include "robot/lost_search.h"
#include "robot/perception.h"
#include "worlds/world.h"

namespace plantsim::robot {

struct TravelSettings {
  controller::PurePursuitParams tracking;  ///< pure pursuit's, when no local controller is chosen
  controller::DockingParams docking;  ///< staging distance and footprint already set from the map
  controller::PotentialFieldParams field;
  double pursuit_replan_period_s = 1.0;
  LostSearchParams lost_search;  ///< driving to find a recognisable view while lost
  CoastalParams coastal;         ///< path travel: routes that keep surfaces in the lidar's sight
  double lidar_range_m = 0;      ///< the lidar's datasheet range (0: no lidar, no coastal route)
  /// The episode's planner on the map; a visibility-graph one is reused for replans (its graph
  /// is never rebuilt: the sensed obstacles are added on top, planner/vg/vg_overlay.h).
  const planner::Planner* map_planner = nullptr;
  /// The local controller that follows the plan (controller/local_controller_registry.h), its
  /// parameters and the facts it is built for; none: pure pursuit of `tracking`.
  const controller::LocalControllerEntry* local = nullptr;
  util::ParamValues local_params;
  controller::LocalControllerContext local_context;
};

/// A new local controller as the settings choose it.
std::unique_ptr<controller::LocalController> make_local_controller(const TravelSettings& s);

/// How a travel ended, when it has.
enum class TravelEnd { kNone, kDocked, kUndocked, kFailed, kTrapped };

struct Decision {
  controller::Twist twist;
  controller::DockPhase phase = controller::DockPhase::kTravel;
  double cross_track_m = 0;
  bool wall_following = false;
  TravelEnd finished = TravelEnd::kNone;  ///< how the travel ended, when it has
  bool blocked = false;                   ///< holding still because the way ahead is not clear
  std::optional<GiveUp> give_up;          ///< why, when it ended without success
  controller::StepEvents events;          ///< what this step did that the episode reports
};

/// What a travel mode has counted.
struct TravelCounts {
  int retries = 0, stops = 0, replans = 0, local_minima = 0, wall_follows = 0, recoveries = 0;
};

class Travel {
 public:
  virtual ~Travel() = default;
  virtual Decision decide(const Perception& p) = 0;
  virtual TravelCounts counts() const = 0;
  /// The plan finally followed (after replans), if it changed.
  virtual std::optional<std::vector<geom::Vec2>> final_plan() const { return std::nullopt; }
};

/// Plans from the estimated pose to `to` on the robot's map with the sensed obstacles added
/// (grown by the arc check's extra clearance, so that the new path is one it will accept): on
/// `map_planner`'s own graph when it is the visibility graph, else with a planner built anew.
std::optional<std::vector<geom::Vec2>> plan_around(const worlds::World& map,
                                                   const std::string& planner_name,
                                                   const controller::DockingParams& docking,
                                                   const geom::Pose2& from, geom::Vec2 to,
                                                   const std::vector<controller::MovingBox>& seen,
                                                   const planner::Planner* map_planner = nullptr);

/// What the robot has sensed, grown as plan_around grows it for the planner.
std::vector<geom::Rect> sensed_blocks(const worlds::World& map,
                                      const controller::DockingParams& docking,
                                      const std::vector<controller::MovingBox>& seen);

/// The docking controller's input from a perception.
controller::DockingInput docking_input(const Perception& p);

/// A docking command as a decision; `finished` when it reports docked or failed (`why`: the
/// controller's own account of a failure).
Decision decision_of(const controller::DockingCommand& cmd,
                     controller::DockFailure why = controller::DockFailure::kNone);

std::unique_ptr<Travel> make_path_travel(const worlds::World& map, const std::string& planner_name,
                                         const TravelSettings& s, std::vector<geom::Vec2> path);
std::unique_ptr<Travel> make_field_travel(const worlds::World& map, const std::string& planner_name,
                                          const TravelSettings& s, bool pursuit,
                                          double robot_radius_m);
std::unique_ptr<Travel> make_pursuit_travel(const worlds::World& map,
                                            const std::string& planner_name,
                                            const TravelSettings& s, std::vector<geom::Vec2> path);
/// `travel`, after holding still for the first `still_s` seconds (the gyro measured at rest).
std::unique_ptr<Travel> hold_still_first(std::unique_ptr<Travel> travel, double still_s);

}  // namespace plantsim::robot
