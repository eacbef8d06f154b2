// The MPPI cycle (see the header).
#include "controller/mppi/mppi_optimizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plantsim::controller::mppi {

MppiOptimizer::MppiOptimizer(MppiParams params, CriticParams critics, std::uint64_t seed)
    : p_(params), c_(critics), rng_(seed), u_(params.time_steps) {
  r_.resize(p_.batch_size, p_.time_steps);
  costs_.resize(p_.batch_size);
}

void MppiOptimizer::set_path(const std::vector<geom::Vec2>& plan, double path_spacing_m) {
  path_.clear();
  path_s_.clear();
  progress_ = 0;
  if (plan.empty()) return;
  path_.push_back(plan.front());
  path_s_.push_back(0.0f);
  double s = 0;
  for (std::size_t i = 1; i < plan.size(); ++i) {
    const geom::Vec2 a = plan[i - 1], b = plan[i];
    const double len = geom::distance(a, b);
    const int pieces = std::max(1, static_cast<int>(std::ceil(len / path_spacing_m)));
    for (int k = 1; k <= pieces; ++k) {
      path_.push_back(a + (static_cast<double>(k) / pieces) * (b - a));
      path_s_.push_back(static_cast<float>(s + len * k / pieces));
    }
    s += len;
  }
}

void MppiOptimizer::prune_path(const RobotState& s) {
  // The nearest point within the next prune_distance (Nav2 prunes the plan the same way): a
  // plan that passes the robot twice is not taken for its later pass.
  window_.clear();
  window_s_.clear();
  if (path_.empty()) return;
  float best = std::numeric_limits<float>::infinity();
  const float reach = path_s_[progress_] + static_cast<float>(p_.prune_distance);
  for (std::size_t k = progress_; k < path_.size() && path_s_[k] <= reach; ++k) {
    const float dx = s.x - static_cast<float>(path_[k].x),
                dy = s.y - static_cast<float>(path_[k].y);
    if (dx * dx + dy * dy < best) best = dx * dx + dy * dy, progress_ = k;
  }
  const float end = path_s_[progress_] + static_cast<float>(p_.prune_distance);
  for (std::size_t k = progress_; k < path_.size() && path_s_[k] <= end; ++k) {
    window_.push_back(path_[k]);
    window_s_.push_back(path_s_[k]);
  }
}

void MppiOptimizer::optimise_once(const MppiQuery& q) {
  draw_noise(p_, rng_, r_);
  roll_out(p_, u_, q.state, r_);
  costs_.setZero();
  const CriticInput in{r_, p_, q.state, window_, window_s_, q.goal, q.clearance, q.robot_radius_m};
  all_critics(in, c_, costs_);
  // The control cost of Williams et al.: gamma / sigma^2 * u . noise, summed over the steps
  // (each a product of the noise table with the sequence).
  const auto gamma = static_cast<float>(p_.gamma);
  costs_ += gamma / static_cast<float>(p_.vx_std * p_.vx_std) *
                (r_.noise_vx.matrix() * u_.vx.matrix()).array() +
            gamma / static_cast<float>(p_.wz_std * p_.wz_std) *
                (r_.noise_wz.matrix() * u_.wz.matrix()).array();
  const float best = costs_.minCoeff();
  weights_ = (-(costs_ - best) / static_cast<float>(p_.temperature)).exp();
  weights_ /= weights_.sum();
  // The samples' own (limited) commands averaged: a sample the limits cut is averaged as driven.
  u_.vx = (r_.vx.matrix().transpose() * weights_.matrix()).array();
  u_.wz = (r_.wz.matrix().transpose() * weights_.matrix()).array();
}

void MppiOptimizer::remember_optimum(const MppiQuery& q) {
  optimal_.clear();
  const auto dt = static_cast<float>(p_.model_dt);
  float x = q.state.x, y = q.state.y, yaw = q.state.yaw;
  for (Eigen::Index t = 0; t < u_.vx.size(); ++t) {
    x += u_.vx(t) * std::cos(yaw) * dt;
    y += u_.vx(t) * std::sin(yaw) * dt;
    yaw += u_.wz(t) * dt;
    optimal_.push_back({x, y, yaw});
  }
}

Twist MppiOptimizer::step(const MppiQuery& q) {
  prune_path(q.state);
  for (int i = 0; i < std::max(1, p_.iteration_count); ++i) optimise_once(q);
  remember_optimum(q);
  const Twist command{u_.vx(0), u_.wz(0)};
  u_.shift();
  return command;
}

std::vector<std::vector<geom::Pose2>> MppiOptimizer::sampled_trajectories(int count) const {
  std::vector<std::vector<geom::Pose2>> out;
  const Eigen::Index rows = r_.x.rows();
  for (int k = 0; k < count && rows > 0; ++k) {
    const Eigen::Index b = (static_cast<Eigen::Index>(k) * rows) / std::max(1, count);
    std::vector<geom::Pose2> poses;
    for (Eigen::Index t = 0; t < r_.x.cols(); ++t)
      poses.push_back({r_.x(b, t), r_.y(b, t), r_.yaw(b, t)});
    out.push_back(std::move(poses));
  }
  return out;
}

}  // namespace plantsim::controller::mppi
