// The critics (see the header). Each cost is a weight times a mean or a sum over the samples'
// steps, as Nav2 forms it with cost_power 1.
#include "controller/mppi/critics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plantsim::controller::mppi {
namespace {

/// Angle differences wrapped to [-pi, pi].
Eigen::ArrayXf wrapped(const Eigen::ArrayXf& a) {
  constexpr float kPi = 3.14159265358979f;
  return a.unaryExpr([](float v) {
    const float w = std::remainder(v, 2.0f * kPi);
    return w > kPi ? w - 2.0f * kPi : w;
  });
}

}  // namespace

float CriticInput::distance_to_goal() const {
  return std::hypot(state.x - static_cast<float>(goal.x), state.y - static_cast<float>(goal.y));
}

void constraint_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  // The samples are already limited; what is left is a speed beyond the limits (none after
  // roll_out, kept for samples that reach the critics otherwise) weighted by time.
  const auto dt = static_cast<float>(in.params.model_dt);
  const Table& v = in.rollouts.vx;
  const Table over = (v - static_cast<float>(in.params.vx_max)).cwiseMax(0.0f) +
                     (static_cast<float>(in.params.vx_min) - v).cwiseMax(0.0f);
  costs += static_cast<float>(c.constraint_weight) * over.rowwise().sum() * dt;
}

void obstacles_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (!in.clearance) return;
  const Rollouts& r = in.rollouts;
  const Eigen::Index batch = r.x.rows(), steps = r.x.cols();
  const bool near_goal = in.distance_to_goal() < c.obstacles_near_goal_distance;
  const auto margin = static_cast<float>(c.collision_margin_distance);
  const auto inflation = static_cast<float>(c.inflation_radius);
  for (Eigen::Index b = 0; b < batch; ++b) {
    float critical = 0, repulsion = 0;
    bool collided = false;
    for (Eigen::Index t = 0; t < steps; ++t) {
      const float d = in.clearance->at(r.x(b, t), r.y(b, t)) - in.robot_radius_m;
      if (d <= 0.0f) {
        collided = true;
        break;
      }
      if (d < margin) critical += margin - d;
      if (!near_goal && d < inflation) repulsion += inflation - d;
    }
    if (collided) {
      costs(b) += static_cast<float>(c.collision_cost);
      continue;
    }
    costs(b) += static_cast<float>(c.critical_weight) * critical / static_cast<float>(steps) +
                static_cast<float>(c.repulsion_weight) * repulsion / static_cast<float>(steps);
  }
}

void goal_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (in.distance_to_goal() > c.goal_threshold_to_consider) return;
  const Rollouts& r = in.rollouts;
  const Table dx = r.x - static_cast<float>(in.goal.x), dy = r.y - static_cast<float>(in.goal.y);
  costs += static_cast<float>(c.goal_weight) * (dx * dx + dy * dy).sqrt().rowwise().mean();
}

void goal_angle_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (in.distance_to_goal() > c.goal_angle_threshold_to_consider) return;
  const Rollouts& r = in.rollouts;
  for (Eigen::Index b = 0; b < r.yaw.rows(); ++b) {
    const Eigen::ArrayXf diff = r.yaw.row(b).transpose() - static_cast<float>(in.goal.yaw);
    costs(b) += static_cast<float>(c.goal_angle_weight) * wrapped(diff).abs().mean();
  }
}

std::size_t furthest_reached(const CriticInput& in) {
  const Rollouts& r = in.rollouts;
  const Eigen::Index last = r.x.cols() - 1;
  std::size_t furthest = 0;
  for (Eigen::Index b = 0; b < r.x.rows(); ++b) {
    float best = std::numeric_limits<float>::infinity();
    std::size_t at = 0;
    for (std::size_t k = 0; k < in.path.size(); ++k) {
      const float dx = r.x(b, last) - static_cast<float>(in.path[k].x);
      const float dy = r.y(b, last) - static_cast<float>(in.path[k].y);
      const float d = dx * dx + dy * dy;
      if (d < best) best = d, at = k;
    }
    furthest = std::max(furthest, at);
  }
  return furthest;
}

/// The index of the path point nearest the robot.
std::size_t nearest_to_robot(const CriticInput& in) {
  std::size_t at = 0;
  float best = std::numeric_limits<float>::infinity();
  for (std::size_t k = 0; k < in.path.size(); ++k) {
    const float dx = in.state.x - static_cast<float>(in.path[k].x);
    const float dy = in.state.y - static_cast<float>(in.path[k].y);
    if (dx * dx + dy * dy < best) best = dx * dx + dy * dy, at = k;
  }
  return at;
}

void path_align_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (in.path.size() < 2 || in.distance_to_goal() < c.path_align_threshold_to_consider) return;
  const std::size_t from = nearest_to_robot(in);
  // A path through something the robot now sees is no line to keep to (Nav2's
  // max_path_occupancy_ratio): the samples must leave it to pass.
  if (in.clearance) {
    const float horizon =
        static_cast<float>(in.params.vx_max * in.params.model_dt * in.params.time_steps);
    std::size_t ahead = 0, blocked = 0;
    for (std::size_t k = from; k < in.path.size() && in.path_s[k] - in.path_s[from] <= horizon;
         ++k, ++ahead)
      blocked += in.clearance->at(static_cast<float>(in.path[k].x),
                                  static_cast<float>(in.path[k].y)) <= in.robot_radius_m;
    if (ahead > 0 && static_cast<double>(blocked) > c.max_path_occupancy_ratio * ahead) return;
  }
  // Each sample's point at arc length s along its own trajectory against the path's point s
  // further along the path than the robot's nearest point: a sample that keeps to the path
  // costs nothing, one that cuts a corner or wanders costs its mean offset.
  const Rollouts& r = in.rollouts;
  const int stride = std::max(1, c.path_align_trajectory_point_step);
  const float start = in.path_s[from], path_end = in.path_s.back();
  for (Eigen::Index b = 0; b < r.x.rows(); ++b) {
    float s = start, px = in.state.x, py = in.state.y, total = 0;
    int counted = 0;
    std::size_t k = from;
    for (Eigen::Index t = 0; t < r.x.cols(); ++t) {
      const float x = r.x(b, t), y = r.y(b, t);
      s += std::hypot(x - px, y - py);
      px = x, py = y;
      if ((t + 1) % stride != 0) continue;
      if (s > path_end) break;
      while (k + 1 < in.path_s.size() && in.path_s[k + 1] <= s) ++k;
      total +=
          std::hypot(x - static_cast<float>(in.path[k].x), y - static_cast<float>(in.path[k].y));
      ++counted;
    }
    if (counted > 0)
      costs(b) += static_cast<float>(c.path_align_weight) * total / static_cast<float>(counted);
  }
}

void path_follow_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (in.path.size() < 2 || in.distance_to_goal() < c.path_follow_threshold_to_consider) return;
  const std::size_t target = std::min(
      in.path.size() - 1, furthest_reached(in) + static_cast<std::size_t>(std::max(
                                                     0, c.path_follow_offset_from_furthest)));
  const Rollouts& r = in.rollouts;
  const Eigen::Index last = r.x.cols() - 1;
  const Eigen::ArrayXf dx = r.x.col(last) - static_cast<float>(in.path[target].x);
  const Eigen::ArrayXf dy = r.y.col(last) - static_cast<float>(in.path[target].y);
  costs += static_cast<float>(c.path_follow_weight) * (dx * dx + dy * dy).sqrt();
}

void path_angle_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (in.path.size() < 2 || in.distance_to_goal() < c.path_angle_threshold_to_consider) return;
  const std::size_t target = std::min(
      in.path.size() - 1, furthest_reached(in) + static_cast<std::size_t>(std::max(
                                                     0, c.path_angle_offset_from_furthest)));
  const auto tx = static_cast<float>(in.path[target].x), ty = static_cast<float>(in.path[target].y);
  // Only when the robot faces away from where the path goes does the heading cost.
  const float now = std::atan2(ty - in.state.y, tx - in.state.x) - in.state.yaw;
  if (std::fabs(std::remainder(now, 6.2831853f)) < c.max_angle_to_furthest) return;
  const Rollouts& r = in.rollouts;
  for (Eigen::Index b = 0; b < r.x.rows(); ++b) {
    Eigen::ArrayXf bearing(r.x.cols());
    for (Eigen::Index t = 0; t < r.x.cols(); ++t)
      bearing(t) = std::atan2(ty - r.y(b, t), tx - r.x(b, t)) - r.yaw(b, t);
    costs(b) += static_cast<float>(c.path_angle_weight) * wrapped(bearing).abs().mean();
  }
}

void prefer_forward_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (in.distance_to_goal() < c.prefer_forward_threshold_to_consider) return;
  const auto dt = static_cast<float>(in.params.model_dt);
  costs += static_cast<float>(c.prefer_forward_weight) *
           (-in.rollouts.vx).cwiseMax(0.0f).rowwise().sum() * dt;
}

void all_critics(const CriticInput& in, const CriticParams& c, Costs& costs) {
  constraint_critic(in, c, costs);
  obstacles_critic(in, c, costs);
  goal_critic(in, c, costs);
  goal_angle_critic(in, c, costs);
  path_align_critic(in, c, costs);
  path_follow_critic(in, c, costs);
  path_angle_critic(in, c, costs);
  prefer_forward_critic(in, c, costs);
}

}  // namespace plantsim::controller::mppi
