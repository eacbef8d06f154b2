// Searching for a place to recognise when the estimator is lost (active relocalisation): a scan
// that fits anywhere along a lone wall, or that sees nothing the map could place, does not
// change while the robot turns on the spot. After one full turn the robot drives, slowly, along
// the nearest surface it sees (a wall's end, a corner, a second building come into view), legs
// of a few metres, turning between them. It steers by the odometry and clears its way by the
// scan's own returns in the robot's frame: neither the map nor the lost estimate is trusted
// (a wall the map puts where the lost estimate expects it is not an obstacle the layer marks).
// Robot side: readings only.
#pragma once

#include <optional>

#include "controller/diff_drive.h"
#include "geometry/vec2.h"
#include "robot/readings.h"

namespace plantsim::robot {

struct LostSearchParams {
  bool enabled = true;
  double speed_mps = 0.3;     ///< driving while lost
  double turn_radps = 0.4;    ///< turning on the spot (the docking controller's look round)
  double leg_m = 4.0;         ///< a leg's length before turning to choose again
  double clearance_m = 0.35;  ///< kept between the footprint's disk and any return ahead
  /// The clearance kept where no way has `clearance_m` (a corridor narrower than the disk and
  /// twice it): legs then run straight along the surface or the freest way in view.
  double narrow_clearance_m = 0.1;
  double standoff_m = 1.5;        ///< distance kept from the surface followed
  double surface_reach_m = 10.0;  ///< surfaces farther than this are not followed
};

class LostSearch {
 public:
  LostSearch(LostSearchParams params, double footprint_radius_m)
      : p_(params), radius_(footprint_radius_m) {}
  /// Forget the search (the estimator is no longer lost).
  void reset();
  /// The twist to drive with while lost: a full turn first, then legs along the nearest
  /// surface. `odom` is the odometry's pose.
  controller::Twist step(const LidarScan& scan, const geom::Pose2& odom);
  /// The search has driven a leg since it began.
  bool driving() const { return driven_; }
  /// Free length ahead along `heading` (robot frame) for the footprint's disk: the distance to
  /// the first return in its way, 0 outside the lidar's field of view.
  double free_ahead(const LidarScan& scan, double heading) const {
    return free_ahead(scan, heading, p_.clearance_m);
  }
  /// The same with `clearance_m` kept in place of the parameter's.
  double free_ahead(const LidarScan& scan, double heading, double clearance_m) const;

 private:
  struct Leg {
    double heading;      // robot frame
    double clearance_m;  // kept along it
  };
  /// The leg along the nearest surface seen, the freer way; where no way is clear by
  /// clearance_m, straight along the surface or the freest way in view with
  /// narrow_clearance_m; none if nothing is clear even so.
  std::optional<Leg> choose_leg(const LidarScan& scan) const;
  std::optional<double> along_surface(const LidarScan& scan, double clearance_m,
                                      bool keep_standoff) const;

  LostSearchParams p_;
  double radius_;
  double turned_rad_ = 0;
  std::optional<double> last_yaw_;
  std::optional<double> target_yaw_;     // odometry frame
  double leg_clearance_m_ = 0;           // the clearance the leg was chosen with
  std::optional<geom::Vec2> leg_start_;  // odometry frame
  bool driven_ = false;
};

}  // namespace plantsim::robot
