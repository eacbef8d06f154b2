// Seed 001's reactive controller: an artificial potential field whose attraction and
// repulsion include relative velocities (moving target, moving obstacles), and the two-state
// machine that switches to wall following when the robot is caught in a local minimum.
//
// The document's formula images are missing; the field is the dynamic potential of Ge and
// Cui (2002) in the document's notation (x robot, x_g target, rho distance to an obstacle,
// v, v_g, v_obs velocities, v_or = (v_obs - v) . e_or):
//   U_att = k_att |x_g - x|^m + k_att_v |v_g - v|^m_v
//   U_rep = 1/2 k_rep (1/rho - 1/rho0)^2 |x - x_g|^n + k_rep_v (1/rho - 1/rho0) v_or^n_v
//           (rho <= rho0; the velocity part only while closing in, v_or > 0)
// whose negative gradients are
//   F_att  = m k_att |x_g - x|^(m-1) e_rg + m_v k_att_v |v_g - v|^(m_v-1) e_gr_v
//   F_rep1 = k_rep (1/rho - 1/rho0) rho^-2 |x - x_g|^n e_or          (away from the obstacle)
//   F_rep2 = n/2 k_rep (1/rho - 1/rho0)^2 |x - x_g|^(n-1) e_rg       (towards the target)
//   F_repv = n_v k_rep_v (1/rho - 1/rho0) v_or^(n_v-1) e_or_v         (along the closing motion)
// (the velocity part grows as the obstacle nears, so that it does not switch on as a step at
// rho0), summed over every obstacle rectangle (walls included) within rho0 of the robot's boundary.
// States and switches are the document's: potential field until F_sum ~ 0 (a local minimum:
// |F_sum| below a fraction of the attraction, or the robot no longer moving, which is how a
// balanced field shows in a robot that has mass); wall following until the projected distance
// to the target, on the line from the local minimum to the target, is smaller than it was at
// the local minimum (d_last > d_now). Speed and turn laws are in docs/config.md.
#pragma once

#include <deque>
#include <vector>

#include "controller/diff_drive.h"
#include "geometry/vec2.h"

namespace plantsim::controller {

using geom::Pose2;
using geom::Vec2;

struct PotentialFieldParams {
  double k_att = 1.0;    ///< position attraction gain (N-like units; forces are unitless)
  double m = 1.0;        ///< exponent of the position attraction (1: constant pull)
  double k_att_v = 0.5;  ///< velocity attraction gain: match the target's velocity
  double m_v = 2.0;
  double k_rep = 0.02;   ///< repulsion gain
  double n = 1.0;        ///< repulsion scales with |x - x_g|^n: vanishes at the target
  double rho0_m = 1.0;   ///< obstacles further than this (from the robot's edge) do not repel
  double k_rep_v = 0.1;  ///< extra repulsion while closing in on an obstacle
  double n_v = 2.0;
  double rho_min_m = 0.02;     ///< distances are clamped here so forces stay finite
  double max_speed_mps = 0.5;  ///< v_max
  double turn_gain = 2.0;      ///< omega_max of the document: yaw rate per radian of heading error
  double max_angular_speed_radps = 1.5;
  double max_decel_mps2 = 0.5;    ///< slow down to stop at a standing target
  double arrive_radius_m = 0.1;   ///< done within this of the target
  double slow_force_ratio = 0.5;  ///< full speed while |F_sum| >= this * k_att, slower below
  double balance_ratio = 0.1;     ///< |F_sum| <= this * k_att: local minimum
  double stall_window_s = 4.0;    ///< moved less than stall_distance in this long: local minimum
  double stall_distance_m = 0.1;
  double wall_distance_m = 0.35;                 ///< d_s: kept from the wall (robot edge to wall)
  double wall_gain = 2.0;                        ///< omega_d: yaw rate per metre of distance error
  double follow_angle_rad = 1.5707963267948966;  ///< alpha: heading relative to the wall normal
  double leave_margin_m =
      0.5;  ///< d_now must be this much below d_last (more than the wall-distance wobble)
  double sensor_range_m = 3.0;  ///< a wall further than this is lost while following
  int max_wall_follows = 20;    ///< more local minima than this: trapped, give up
};

/// An obstacle as the field sees it: a rectangle and its velocity (zero for static ones).
struct FieldObstacle {
  geom::Rect box;
  Vec2 velocity;
};

struct FieldForces {
  Vec2 attraction, repulsion, total;
  double nearest_m = INFINITY;  ///< robot edge to the nearest obstacle within sensor range
  Vec2 nearest_normal;          ///< unit, from that obstacle towards the robot
};

/// The forces on a disk robot of `radius_m` at x moving with v, towards target x_g moving with v_g.
FieldForces field_forces(const PotentialFieldParams& p, double radius_m, Vec2 x, Vec2 v, Vec2 x_g,
                         Vec2 v_g, const std::vector<FieldObstacle>& obstacles);

enum class FieldState { kPotentialField, kWallFollowing };

struct FieldInput {
  Pose2 pose;     ///< estimated
  Vec2 velocity;  ///< estimated, world frame
  Vec2 target;
  Vec2 target_velocity;
  double dt_s = 0;
  std::vector<FieldObstacle> obstacles;  ///< everything sensed (static and moving)
};

struct FieldCommand {
  Twist twist;
  FieldState state = FieldState::kPotentialField;
  bool arrived = false;
  bool trapped = false;  ///< gave up after max_wall_follows local minima
  FieldForces forces;
};

class PotentialFieldController {
 public:
  PotentialFieldController(PotentialFieldParams params, double robot_radius_m);

  FieldCommand step(const FieldInput& in);

  int local_minima() const { return local_minima_; }
  int wall_follow_episodes() const { return wall_follows_; }
  FieldState state() const { return state_; }

 private:
  Twist field_motion(const FieldInput& in, const FieldForces& f) const;
  Twist wall_motion(const FieldInput& in);
  bool stalled(const FieldInput& in);

  PotentialFieldParams p_;
  double radius_m_;
  FieldState state_ = FieldState::kPotentialField;
  int local_minima_ = 0;
  int wall_follows_ = 0;
  bool trapped_ = false;
  Vec2 trap_point_;  // where the last local minimum was met
  double wall_side_ =
      1.0;  // +1: wall on the right (theta_exp = theta_rep - alpha); -1: on the left
  Vec2 last_normal_{1, 0};  // wall to robot, as last seen while following
  double clock_s_ = 0;
  std::deque<std::pair<double, Vec2>> history_;  // (time, position) while in the field state
};

}  // namespace plantsim::controller
