// DWB's cycle (see the header).
#include "controller/dwb/dwb_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plantsim::controller::dwb {
namespace {

constexpr double kCell_m = 0.05;  // the map-grid critics' unit
constexpr double kLethal = 254, kInscribed = 253, kCostScaling = 10.0;

int sign(double v) { return (v > 1e-6) - (v < -1e-6); }

double wrapped(double a) { return std::remainder(a, 2.0 * M_PI); }

/// The values n samples spread evenly over [lo, hi] (one sample: hi).
std::vector<double> spread(double lo, double hi, int n) {
  std::vector<double> out;
  if (n <= 1 || hi <= lo) return {hi};
  for (int i = 0; i < n; ++i) out.push_back(lo + (hi - lo) * i / (n - 1));
  return out;
}

}  // namespace

DwbPlanner::DwbPlanner(DwbParams params) : p_(params) {}

void DwbPlanner::set_path(const std::vector<geom::Vec2>& plan) {
  path_.clear();
  for (std::size_t i = 0; i < plan.size(); ++i) {
    if (i == 0) {
      path_.push_back(plan[0]);
      continue;
    }
    const double len = geom::distance(plan[i - 1], plan[i]);
    const int pieces = std::max(1, static_cast<int>(std::ceil(len / kCell_m)));
    for (int k = 1; k <= pieces; ++k)
      path_.push_back(plan[i - 1] + (static_cast<double>(k) / pieces) * (plan[i] - plan[i - 1]));
  }
  flipped_at_.reset();
  progress_ = 0;
  window_ = path_;
}

void DwbPlanner::prune(geom::Vec2 robot) {
  if (path_.empty()) return;
  // The nearest point within the next forward_prune_distance (DWB prunes the plan the same
  // way), so that a plan passing the robot twice is not taken for its later pass.
  const auto reach = static_cast<std::size_t>(p_.forward_prune_distance / kCell_m);
  double best = std::numeric_limits<double>::infinity();
  const std::size_t from = progress_;
  for (std::size_t k = from; k < path_.size() && k <= from + reach; ++k)
    if (const double d = geom::distance(path_[k], robot); d < best) best = d, progress_ = k;
  window_.assign(
      path_.begin() + static_cast<std::ptrdiff_t>(progress_),
      path_.begin() + static_cast<std::ptrdiff_t>(std::min(path_.size(), progress_ + reach + 1)));
}

std::vector<geom::Pose2> DwbPlanner::simulate(const DwbQuery& q, Twist target) const {
  std::vector<geom::Pose2> poses;
  geom::Pose2 s = q.pose;
  double v = q.velocity.v_mps, w = q.velocity.omega_radps;
  const double dt = p_.time_granularity;
  for (double t = 0; t < p_.sim_time - 1e-9; t += dt) {
    // Towards the target speeds as fast as the limits allow (DWB's generator ramps the same).
    v = std::clamp(target.v_mps, v + p_.decel_lim_x * dt, v + p_.acc_lim_x * dt);
    const double dw =
        (std::fabs(target.omega_radps) > std::fabs(w) ? p_.acc_lim_theta : -p_.decel_lim_theta) *
        dt;
    w = std::clamp(target.omega_radps, w - dw, w + dw);
    s.x += v * std::cos(s.yaw) * dt;
    s.y += v * std::sin(s.yaw) * dt;
    s.yaw += w * dt;
    poses.push_back(s);
  }
  return poses;
}

double DwbPlanner::path_distance_cells(geom::Vec2 p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const geom::Vec2& a : window_) best = std::min(best, geom::distance(a, p));
  return best / kCell_m;
}

ScoredTrajectory DwbPlanner::score(const DwbQuery& q, Twist command) const {
  ScoredTrajectory t;
  t.command = command;
  t.poses = simulate(q, command);
  if (t.poses.empty()) return t;
  // BaseObstacle: the sum of the costmap's costs under the trajectory (inflation's exponential
  // decay from the footprint's edge); a pose in collision rejects the trajectory.
  if (q.clearance) {
    double sum = 0;
    for (const geom::Pose2& s : t.poses) {
      const double d =
          q.clearance->at(static_cast<float>(s.x), static_cast<float>(s.y)) - q.robot_radius_m;
      if (d <= 0) {
        t.valid = false;
        break;
      }
      if (d < p_.inflation_radius_m) sum += (kInscribed - 1) * std::exp(-kCostScaling * d);
    }
    t.obstacle = p_.base_obstacle_scale * sum;
  }
  if (!t.valid) return t;
  // Oscillation: a reversal of forward or turning direction before the robot moved
  // oscillation_reset_dist since the last one.
  const bool flips_v = last_v_sign_ != 0 && sign(command.v_mps) == -last_v_sign_;
  const bool flips_w = last_w_sign_ != 0 && sign(command.omega_radps) == -last_w_sign_;
  if ((flips_v || flips_w) && flipped_at_ &&
      geom::distance(*flipped_at_, q.pose.position()) < p_.oscillation_reset_dist) {
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
  if (window_.empty()) return t;
  const geom::Vec2 ahead{end.x + p_.forward_point_distance * std::cos(end.yaw),
                         end.y + p_.forward_point_distance * std::sin(end.yaw)};
  t.path_dist = p_.path_dist_scale * path_distance_cells(end.position());
  t.goal_dist = p_.goal_dist_scale * geom::distance(end.position(), window_.back()) / kCell_m;
  // The point ahead overshoots a goal nearer than it: there the align critics are silent
  // (DWB's alignment critics zero their scale the same way).
  if (to_goal > p_.forward_point_distance) {
    t.path_align = p_.path_align_scale * path_distance_cells(ahead);
    t.goal_align = p_.goal_align_scale * geom::distance(ahead, window_.back()) / kCell_m;
  }
  return t;
}

Twist DwbPlanner::step(const DwbQuery& q) {
  // The dynamic window: what one controller period of acceleration reaches from now.
  const double dt = p_.controller_period;
  const double v0 = q.velocity.v_mps, w0 = q.velocity.omega_radps;
  const double v_lo = std::max(p_.min_vel_x, v0 + p_.decel_lim_x * dt);
  const double v_hi = std::min(p_.max_vel_x, v0 + p_.acc_lim_x * dt);
  const double w_lo = std::max(-p_.max_vel_theta, w0 + p_.decel_lim_theta * dt);
  const double w_hi = std::min(p_.max_vel_theta, w0 + p_.acc_lim_theta * dt);
  prune(q.pose.position());
  scored_.clear();
  for (double v : spread(v_lo, std::max(v_lo, v_hi), p_.vx_samples))
    for (double w : spread(w_lo, std::max(w_lo, w_hi), p_.vtheta_samples)) {
      if (std::fabs(v) < 1e-6 && std::fabs(w) < p_.min_speed_theta) continue;
      scored_.push_back(score(q, {v, w}));
    }
  const ScoredTrajectory* best = nullptr;
  for (const ScoredTrajectory& t : scored_)
    if (t.valid && (!best || t.total() < best->total())) best = &t;
  const Twist command = best ? best->command : Twist{0, 0};
  const int vs = sign(command.v_mps), ws = sign(command.omega_radps);
  if ((last_v_sign_ != 0 && vs == -last_v_sign_) || (last_w_sign_ != 0 && ws == -last_w_sign_))
    flipped_at_ = q.pose.position();
  if (vs != 0) last_v_sign_ = vs;
  if (ws != 0) last_w_sign_ = ws;
  return command;
}

}  // namespace plantsim::controller::dwb
