// DWB's cycle (see the header).
#include "controller/dwb/dwb_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plantsim::controller::dwb {
namespace {

constexpr double kCell_m = PlanWindow::kSpacing_m;  // the map-grid critics' unit
constexpr double kInscribed = 253, kCostScaling = 10.0;

double wrapped(double a) { return std::remainder(a, 2.0 * M_PI); }

/// The values n samples spread evenly over [lo, hi] (one sample: hi).
std::vector<double> spread(double lo, double hi, int n) {
  std::vector<double> out;
  if (n <= 1 || hi <= lo) return {hi};
  for (int i = 0; i < n; ++i) out.push_back(lo + (hi - lo) * i / (n - 1));
  return out;
}

}  // namespace

DwbPlanner::DwbPlanner(DwbParams params)
    : p_(params),
      oscillation_({p_.oscillation_reset_dist, p_.oscillation_reset_angle, p_.x_only_threshold}) {}

void DwbPlanner::set_path(const std::vector<geom::Vec2>& plan) {
  plan_.set_path(plan);
  oscillation_.reset();
}

std::vector<geom::Pose2> DwbPlanner::simulate(const DwbQuery& q, Twist target) const {
  std::vector<geom::Pose2> poses;
  poses.reserve(static_cast<std::size_t>(std::ceil(p_.sim_time / p_.time_granularity)) + 1);
  geom::Pose2 s = q.pose;
  // The heading as its cosine and sine, turned pose by pose (a step turns at most
  // max_vel_theta * time_granularity, 0.025 rad): no trigonometry per pose.
  double c = std::cos(s.yaw), sn = std::sin(s.yaw);
  double v = q.velocity.v_mps, w = q.velocity.omega_radps;
  const double dt = p_.time_granularity;
  for (double t = 0; t < p_.sim_time - 1e-9; t += dt) {
    // Towards the target speeds as fast as the limits allow (DWB's generator ramps the same).
    v = std::clamp(target.v_mps, v + p_.decel_lim_x * dt, v + p_.acc_lim_x * dt);
    const double dw =
        (std::fabs(target.omega_radps) > std::fabs(w) ? p_.acc_lim_theta : -p_.decel_lim_theta) *
        dt;
    w = std::clamp(target.omega_radps, w - dw, w + dw);
    s.x += v * c * dt;
    s.y += v * sn * dt;
    s.yaw += w * dt;
    const double a = w * dt, a2 = a * a;
    const double rc = 1 - a2 * (0.5 - a2 * (1.0 / 24 - a2 / 720));
    const double rs = a * (1 - a2 * (1.0 / 6 - a2 * (1.0 / 120 - a2 / 5040)));
    const double turned = c * rc - sn * rs;
    sn = sn * rc + c * rs, c = turned;
    poses.push_back(s);
  }
  return poses;
}

double DwbPlanner::edge_distance(const DwbQuery& q, const geom::Pose2& s) {
  return q.clearance->interpolated(static_cast<float>(s.x), static_cast<float>(s.y)) -
         q.robot_radius_m;
}

double DwbPlanner::path_distance_cells(geom::Vec2 p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const geom::Vec2& a : plan_.window())
    best = std::min(best, (a.x - p.x) * (a.x - p.x) + (a.y - p.y) * (a.y - p.y));
  return std::sqrt(best) / kCell_m;
}

ScoredTrajectory DwbPlanner::score(const DwbQuery& q, Twist command) const {
  ScoredTrajectory t;
  t.command = command;
  t.poses = simulate(q, command);
  if (t.poses.empty()) return t;
  // BaseObstacle: the sum of the costmap's costs under the trajectory (inflation's exponential
  // decay from the footprint's edge); a pose in collision rejects the trajectory.
  if (q.clearance) {
    // A pose the footprint overlaps is a collision, unless the robot overlaps as much where it
    // stands (the field's cells are coarser than the plan's margin): it may turn or leave.
    const double here = edge_distance(q, q.pose);
    double sum = 0;
    for (const geom::Pose2& s : t.poses) {
      const double d = edge_distance(q, s);
      if (d <= 0 && d < here) {
        t.valid = false;
        break;
      }
      if (d < p_.inflation_radius_m)
        sum += (kInscribed - 1) * std::exp(-kCostScaling * std::max(0.0, d));
    }
    t.obstacle = p_.base_obstacle_scale * sum;
  }
  if (!t.valid) return t;
  if (oscillation_.oscillating(command)) {
    t.valid = false;
    return t;
  }
  const geom::Pose2& end = t.poses.back();
  const double to_goal = geom::distance(q.pose.position(), q.goal.position());
  if (to_goal <= p_.xy_goal_tolerance) {
    // RotateToGoal: at the goal only the heading matters, and any speed costs.
    t.rotate = p_.rotate_to_goal_scale * (std::fabs(wrapped(end.yaw - q.goal.yaw)) +
                                          p_.slowing_factor * std::fabs(command.v_mps));
    return t;
  }
  if (plan_.window().empty()) return t;
  const geom::Vec2 goal = plan_.local_goal();
  const geom::Vec2 ahead{end.x + p_.forward_point_distance * std::cos(end.yaw),
                         end.y + p_.forward_point_distance * std::sin(end.yaw)};
  t.path_dist = p_.path_dist_scale * path_distance_cells(end.position());
  t.goal_dist = p_.goal_dist_scale * geom::distance(end.position(), goal) / kCell_m;
  // The point ahead overshoots a goal nearer than it: there the align critics are silent (DWB's
  // alignment critics zero their scale the same way), at the plan's end and at a corner the
  // robot is about to reach, where it turns to the plan beyond once it sees it.
  const bool corner_near =
      plan_.goal_at_corner() && geom::distance(q.pose.position(), goal) <
                                    p_.forward_point_distance + p_.max_vel_x * p_.sim_time;
  if (to_goal > p_.forward_point_distance && !corner_near) {
    t.path_align = p_.path_align_scale * path_distance_cells(ahead);
    t.goal_align = p_.goal_align_scale * geom::distance(ahead, goal) / kCell_m;
  }
  return t;
}

Twist DwbPlanner::step(const DwbQuery& q) {
  // The dynamic window: what sim_time of acceleration reaches from now (Nav2's
  // StandardTrajectoryGenerator; its LimitedAccelGenerator would use the controller period).
  const double dt = p_.sim_time;
  const double v0 = q.velocity.v_mps, w0 = q.velocity.omega_radps;
  const double v_lo = std::max(p_.min_vel_x, v0 + p_.decel_lim_x * dt);
  const double v_hi = std::min(p_.max_vel_x, v0 + p_.acc_lim_x * dt);
  const double w_lo = std::max(-p_.max_vel_theta, w0 + p_.decel_lim_theta * dt);
  const double w_hi = std::min(p_.max_vel_theta, w0 + p_.acc_lim_theta * dt);
  plan_.update(q.pose.position(), p_.forward_prune_distance, q.clearance, q.robot_radius_m,
               p_.local_goal_margin_m);
  scored_.clear();
  for (double v : spread(v_lo, std::max(v_lo, v_hi), p_.vx_samples))
    for (double w : spread(w_lo, std::max(w_lo, w_hi), p_.vtheta_samples)) {
      if (std::fabs(v) < 1e-6 && std::fabs(w) < p_.min_speed_theta) continue;
      scored_.push_back(score(q, {v, w}));
    }
  chosen_ = -1;
  for (std::size_t k = 0; k < scored_.size(); ++k)
    if (scored_[k].valid &&
        (chosen_ < 0 || scored_[k].total() < scored_[static_cast<std::size_t>(chosen_)].total()))
      chosen_ = static_cast<int>(k);
  const Twist command = chosen() ? chosen()->command : Twist{0, 0};
  oscillation_.sent(command, q.pose);
  return command;
}

}  // namespace plantsim::controller::dwb
