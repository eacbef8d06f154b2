// The dynamic potential field, its two states and their motion laws.
#include "controller/potential_field.h"

#include <algorithm>
#include <cmath>

namespace plantsim::controller {
namespace {

Vec2 unit_or_zero(Vec2 a) {
  const double n = geom::norm(a);
  return n > 0 ? (1.0 / n) * a : Vec2{0, 0};
}

double angle_of(Vec2 a) { return std::atan2(a.y, a.x); }

struct WallContact {
  double distance_m = INFINITY;  // robot edge to the wall
  Vec2 normal;                   // unit, wall to robot
};

// The nearest obstacle on the followed side (side +1: right) or straight ahead within the
// robot's width: an obstacle on the other side (across a gap) is not the wall being followed.
WallContact wall_on_side(const std::vector<FieldObstacle>& obstacles, const Pose2& pose,
                         double side, double radius_m, double range_m) {
  WallContact w;
  const Vec2 x = pose.position(), h = pose.heading();
  for (const FieldObstacle& o : obstacles) {
    const Vec2 rel = geom::closest_point(o.box, x) - x;
    const double d = geom::norm(rel) - radius_m;
    if (d >= w.distance_m || d > range_m) continue;
    const double lateral = side * geom::cross(h, rel);  // > 0: on the other side
    if (lateral > 0 && !(geom::dot(h, rel) > 0 && lateral < radius_m)) continue;
    w.distance_m = std::max(d, 0.0);
    w.normal = geom::norm(rel) > 0 ? (-1.0 / geom::norm(rel)) * rel : Vec2{-h.x, -h.y};
  }
  return w;
}

}  // namespace

FieldForces field_forces(const PotentialFieldParams& p, double radius_m, Vec2 x, Vec2 v, Vec2 x_g,
                         Vec2 v_g, const std::vector<FieldObstacle>& obstacles) {
  FieldForces f;
  const double goal_distance = geom::distance(x, x_g);
  const Vec2 e_rg = unit_or_zero(x_g - x);
  const Vec2 dv = v_g - v;
  const double dv_norm = geom::norm(dv);
  f.attraction = p.m * p.k_att * std::pow(goal_distance, p.m - 1.0) * e_rg;
  if (dv_norm > 0)
    f.attraction =
        f.attraction + p.m_v * p.k_att_v * std::pow(dv_norm, p.m_v - 1.0) * ((1.0 / dv_norm) * dv);

  for (const FieldObstacle& o : obstacles) {
    const Vec2 q = geom::closest_point(o.box, x);
    Vec2 away = x - q;
    double centre_distance = geom::norm(away);
    if (centre_distance ==
        0) {  // inside the box (only after a collision): push out from its centre
      away = x - o.box.center();
      centre_distance = 0;
    }
    const Vec2 e_or = unit_or_zero(away);
    const double rho_edge = centre_distance - radius_m;
    if (rho_edge < f.nearest_m && rho_edge <= p.sensor_range_m) {
      f.nearest_m = std::max(rho_edge, 0.0);
      f.nearest_normal = e_or;
    }
    if (rho_edge > p.rho0_m) continue;
    const double rho = std::max(rho_edge, p.rho_min_m);
    const double s = 1.0 / rho - 1.0 / p.rho0_m;
    Vec2 rep = p.k_rep * s / (rho * rho) * std::pow(goal_distance, p.n) * e_or;
    rep = rep + 0.5 * p.n * p.k_rep * s * s * std::pow(goal_distance, p.n - 1.0) * e_rg;
    const Vec2 closing = o.velocity - v;  // obstacle velocity relative to the robot
    const double v_or = geom::dot(closing, e_or);
    if (v_or > 0)
      rep = rep + p.n_v * p.k_rep_v * s * std::pow(v_or, p.n_v - 1.0) * unit_or_zero(closing);
    f.repulsion = f.repulsion + rep;
  }
  f.total = f.attraction + f.repulsion;
  return f;
}

PotentialFieldController::PotentialFieldController(PotentialFieldParams params,
                                                   double robot_radius_m)
    : p_(params), radius_m_(robot_radius_m) {}

bool PotentialFieldController::stalled(const FieldInput& in) {
  history_.emplace_back(clock_s_, in.pose.position());
  while (history_.size() > 2 && history_[1].first <= clock_s_ - p_.stall_window_s)
    history_.pop_front();
  if (history_.front().first > clock_s_ - p_.stall_window_s)
    return false;  // not watched long enough
  return geom::distance(history_.front().second, in.pose.position()) < p_.stall_distance_m;
}

Twist PotentialFieldController::field_motion(const FieldInput& in, const FieldForces& f) const {
  // Heading towards the resultant; speed falls as the forces balance and as the heading
  // turns away from it; stop at a standing target; omega = omega_max (theta_res - theta_0).
  const double heading_error = geom::wrap_angle(angle_of(f.total) - in.pose.yaw);
  const double strength = std::min(1.0, geom::norm(f.total) / (p_.slow_force_ratio * p_.k_att));
  double v = p_.max_speed_mps * std::max(0.0, std::cos(heading_error)) * strength;
  const double to_go =
      std::max(0.0, geom::distance(in.pose.position(), in.target) - p_.arrive_radius_m);
  v = std::min(v, geom::norm(in.target_velocity) + std::sqrt(2.0 * p_.max_decel_mps2 * to_go));
  const double w = std::clamp(p_.turn_gain * heading_error, -p_.max_angular_speed_radps,
                              p_.max_angular_speed_radps);
  return {v, w};
}

Twist PotentialFieldController::wall_motion(const FieldInput& in) {
  // The document's laws: v = v_max (1 - |cos(theta_rep - theta_0)|),
  // omega = omega_max (theta_exp - theta_0) + omega_d (d_0 - d_s), theta_exp = theta_rep -/+ alpha.
  const WallContact wall =
      wall_on_side(in.obstacles, in.pose, wall_side_, radius_m_, p_.sensor_range_m);
  // A lost wall (rounding a thin end) is looked for where it was last seen.
  if (std::isfinite(wall.distance_m)) last_normal_ = wall.normal;
  const double theta_rep = angle_of(last_normal_);
  const double theta_exp = theta_rep - wall_side_ * p_.follow_angle_rad;
  const double d0 = std::isfinite(wall.distance_m) ? wall.distance_m : p_.sensor_range_m;
  const double v = p_.max_speed_mps * (1.0 - std::fabs(std::cos(theta_rep - in.pose.yaw)));
  // Further than d_s from a wall on the right means turning right (clockwise), and vice versa.
  const double w = p_.turn_gain * geom::wrap_angle(theta_exp - in.pose.yaw) -
                   wall_side_ * p_.wall_gain * (d0 - p_.wall_distance_m);
  return {v, std::clamp(w, -p_.max_angular_speed_radps, p_.max_angular_speed_radps)};
}

FieldCommand PotentialFieldController::step(const FieldInput& in) {
  clock_s_ += in.dt_s;
  FieldCommand out;
  const Vec2 x = in.pose.position();
  out.forces =
      field_forces(p_, radius_m_, x, in.velocity, in.target, in.target_velocity, in.obstacles);
  if (trapped_) {
    out.trapped = true;
    out.state = state_;
    return out;
  }
  if (geom::distance(x, in.target) <= p_.arrive_radius_m) {
    out.arrived = true;
    out.state = state_;
    return out;
  }

  if (state_ == FieldState::kPotentialField) {
    const bool balanced = geom::norm(out.forces.total) <= p_.balance_ratio * p_.k_att;
    const bool near_obstacle = std::isfinite(out.forces.nearest_m);
    if ((balanced || stalled(in)) && near_obstacle) {
      ++local_minima_;
      if (local_minima_ > p_.max_wall_follows) {
        trapped_ = out.trapped = true;
        return out;
      }
      ++wall_follows_;
      state_ = FieldState::kWallFollowing;
      trap_point_ = x;
      history_.clear();
      // Follow the wall on the side whose travel direction is nearer the target's direction.
      last_normal_ = out.forces.nearest_normal;
      const double theta_rep = angle_of(last_normal_), to_target = angle_of(in.target - x);
      const double right = std::fabs(geom::wrap_angle(theta_rep - p_.follow_angle_rad - to_target));
      const double left = std::fabs(geom::wrap_angle(theta_rep + p_.follow_angle_rad - to_target));
      wall_side_ = right <= left ? 1.0 : -1.0;
    }
  } else {
    // d_last: the target's distance from the local minimum; d_now: the robot's distance to the
    // target projected on that line. Read per step, "d_now < d_last" would end wall following
    // at its first step forward and drop the robot back into the same minimum.
    const Vec2 line = in.target - trap_point_;
    const double d_last = geom::norm(line);
    const double d_now = d_last > 0 ? geom::dot(in.target - x, (1.0 / d_last) * line) : 0.0;
    if (d_last - d_now > p_.leave_margin_m) {
      state_ = FieldState::kPotentialField;
      history_.clear();
    }
  }
  out.state = state_;
  out.twist =
      state_ == FieldState::kPotentialField ? field_motion(in, out.forces) : wall_motion(in);
  return out;
}

}  // namespace plantsim::controller
