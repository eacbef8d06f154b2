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
  const auto w = static_cast<float>(c.constraint_weight * in.params.model_dt);
  const auto hi = static_cast<float>(in.params.vx_max), lo = static_cast<float>(in.params.vx_min);
  const Table& v = in.rollouts.vx;
  for (Eigen::Index t = 0; t < v.cols(); ++t)
    costs += w * ((v.col(t) - hi).max(0.0f) + (lo - v.col(t)).max(0.0f));
}

void obstacles_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (!in.clearance) return;
  const Rollouts& r = in.rollouts;
  const Eigen::Index batch = r.x.rows(), steps = r.x.cols();
  const bool near_goal = in.distance_to_goal() < c.obstacles_near_goal_distance;
  const auto margin = static_cast<float>(c.collision_margin_distance);
  const auto inflation = near_goal ? 0.0f : static_cast<float>(c.inflation_radius);
  // Step by step over the whole batch: a collided sample's sums no longer matter (its cost is
  // the collision's), so they are summed on without a branch.
  Eigen::ArrayXf critical = Eigen::ArrayXf::Zero(batch), repulsion = critical;
  Eigen::ArrayXf nearest = Eigen::ArrayXf::Constant(batch, INFINITY);
  for (Eigen::Index t = 0; t < steps; ++t) {
    const float* x = r.x.col(t).data();
    const float* y = r.y.col(t).data();
    for (Eigen::Index b = 0; b < batch; ++b) {
      const float d = in.clearance->at(x[b], y[b]) - in.robot_radius_m;
      nearest(b) = std::min(nearest(b), d);
      critical(b) += std::max(margin - d, 0.0f);
      repulsion(b) += std::max(inflation - d, 0.0f);
    }
  }
  const auto per_step = 1.0f / static_cast<float>(steps);
  costs += (nearest <= 0.0f)
               .select(static_cast<float>(c.collision_cost),
                       static_cast<float>(c.critical_weight) * per_step * critical +
                           static_cast<float>(c.repulsion_weight) * per_step * repulsion);
}

void goal_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (in.distance_to_goal() > c.goal_threshold_to_consider) return;
  const Rollouts& r = in.rollouts;
  const auto w = static_cast<float>(c.goal_weight) / static_cast<float>(r.x.cols());
  const auto gx = static_cast<float>(in.goal.x), gy = static_cast<float>(in.goal.y);
  for (Eigen::Index t = 0; t < r.x.cols(); ++t)
    costs += w * ((r.x.col(t) - gx).square() + (r.y.col(t) - gy).square()).sqrt();
}

void goal_angle_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (in.distance_to_goal() > c.goal_angle_threshold_to_consider) return;
  const Rollouts& r = in.rollouts;
  const auto w = static_cast<float>(c.goal_angle_weight) / static_cast<float>(r.yaw.cols());
  for (Eigen::Index t = 0; t < r.yaw.cols(); ++t)
    costs += w * wrapped(r.yaw.col(t) - static_cast<float>(in.goal.yaw)).abs();
}

std::size_t furthest_reached(const CriticInput& in) {
  const Rollouts& r = in.rollouts;
  const Eigen::Index last = r.x.cols() - 1;
  const float* ex = r.x.col(last).data();
  const float* ey = r.y.col(last).data();
  std::vector<float> px(in.path.size()), py(in.path.size());
  for (std::size_t k = 0; k < in.path.size(); ++k)
    px[k] = static_cast<float>(in.path[k].x), py[k] = static_cast<float>(in.path[k].y);
  std::size_t furthest = 0;
  for (Eigen::Index b = 0; b < r.x.rows(); ++b) {
    float best = std::numeric_limits<float>::infinity();
    std::size_t at = 0;
    for (std::size_t k = 0; k < px.size(); ++k) {
      const float dx = ex[b] - px[k], dy = ey[b] - py[k];
      const float d = dx * dx + dy * dy;
      if (d < best) best = d, at = k;
    }
    furthest = std::max(furthest, at);
  }
  return furthest;
}

std::size_t furthest_of(const CriticInput& in) {
  return in.furthest != static_cast<std::size_t>(-1) ? in.furthest : furthest_reached(in);
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
  // costs nothing, one that cuts a corner or wanders costs its mean offset. Step by step over
  // the batch, each sample's arc length, place on the path and sums carried along.
  const Rollouts& r = in.rollouts;
  const Eigen::Index batch = r.x.rows();
  const int stride = std::max(1, c.path_align_trajectory_point_step);
  const float path_end = in.path_s.back();
  Eigen::ArrayXf s = Eigen::ArrayXf::Constant(batch, in.path_s[from]),
                 total = Eigen::ArrayXf::Zero(batch);
  Eigen::ArrayXf counted = Eigen::ArrayXf::Zero(batch);
  std::vector<std::size_t> k(static_cast<std::size_t>(batch), from);
  std::vector<unsigned char> done(static_cast<std::size_t>(batch), 0);
  for (Eigen::Index t = 0; t < r.x.cols(); ++t) {
    const float* x = r.x.col(t).data();
    const float* y = r.y.col(t).data();
    const float* px = t > 0 ? r.x.col(t - 1).data() : nullptr;
    const float* py = t > 0 ? r.y.col(t - 1).data() : nullptr;
    const bool counts = (t + 1) % stride == 0;
    for (Eigen::Index b = 0; b < batch; ++b) {
      const float dx = x[b] - (px ? px[b] : in.state.x), dy = y[b] - (py ? py[b] : in.state.y);
      s(b) += std::sqrt(dx * dx + dy * dy);
      if (!counts || done[static_cast<std::size_t>(b)]) continue;
      if (s(b) > path_end) {
        done[static_cast<std::size_t>(b)] = 1;
        continue;
      }
      std::size_t& at = k[static_cast<std::size_t>(b)];
      while (at + 1 < in.path_s.size() && in.path_s[at + 1] <= s(b)) ++at;
      const float ox = x[b] - static_cast<float>(in.path[at].x);
      const float oy = y[b] - static_cast<float>(in.path[at].y);
      total(b) += std::sqrt(ox * ox + oy * oy);
      counted(b) += 1.0f;
    }
  }
  costs += (counted > 0.0f)
               .select(static_cast<float>(c.path_align_weight) * total / counted.max(1.0f), 0.0f);
}

void path_follow_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (in.path.size() < 2 || in.distance_to_goal() < c.path_follow_threshold_to_consider) return;
  const std::size_t target = std::min(
      in.path.size() - 1,
      furthest_of(in) + static_cast<std::size_t>(std::max(0, c.path_follow_offset_from_furthest)));
  const Rollouts& r = in.rollouts;
  const Eigen::Index last = r.x.cols() - 1;
  const Eigen::ArrayXf dx = r.x.col(last) - static_cast<float>(in.path[target].x);
  const Eigen::ArrayXf dy = r.y.col(last) - static_cast<float>(in.path[target].y);
  costs += static_cast<float>(c.path_follow_weight) * (dx * dx + dy * dy).sqrt();
}

void path_angle_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (in.path.size() < 2 || in.distance_to_goal() < c.path_angle_threshold_to_consider) return;
  const std::size_t target = std::min(
      in.path.size() - 1,
      furthest_of(in) + static_cast<std::size_t>(std::max(0, c.path_angle_offset_from_furthest)));
  const auto tx = static_cast<float>(in.path[target].x), ty = static_cast<float>(in.path[target].y);
  // Only when the robot faces away from where the path goes does the heading cost.
  const float now = std::atan2(ty - in.state.y, tx - in.state.x) - in.state.yaw;
  if (std::fabs(std::remainder(now, 6.2831853f)) < c.max_angle_to_furthest) return;
  const Rollouts& r = in.rollouts;
  const auto w = static_cast<float>(c.path_angle_weight) / static_cast<float>(r.x.cols());
  Eigen::ArrayXf bearing(r.x.rows());
  for (Eigen::Index t = 0; t < r.x.cols(); ++t) {
    for (Eigen::Index b = 0; b < r.x.rows(); ++b)
      bearing(b) = std::atan2(ty - r.y(b, t), tx - r.x(b, t)) - r.yaw(b, t);
    costs += w * wrapped(bearing).abs();
  }
}

void prefer_forward_critic(const CriticInput& in, const CriticParams& c, Costs& costs) {
  if (in.distance_to_goal() < c.prefer_forward_threshold_to_consider) return;
  const auto w = static_cast<float>(c.prefer_forward_weight * in.params.model_dt);
  for (Eigen::Index t = 0; t < in.rollouts.vx.cols(); ++t)
    costs += w * (-in.rollouts.vx.col(t)).max(0.0f);
}

void all_critics(const CriticInput& in, const CriticParams& c, Costs& costs) {
  CriticInput with = in;
  if (in.path.size() >= 2) with.furthest = furthest_reached(in);
  constraint_critic(with, c, costs);
  obstacles_critic(with, c, costs);
  goal_critic(with, c, costs);
  goal_angle_critic(with, c, costs);
  path_align_critic(with, c, costs);
  path_follow_critic(with, c, costs);
  path_angle_critic(with, c, costs);
  prefer_forward_critic(with, c, costs);
}

}  // namespace plantsim::controller::mppi
