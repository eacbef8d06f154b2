// Sampling and integrating MPPI's control sequences (see the header).
#include "controller/mppi/rollouts.h"

#include <algorithm>
#include <cmath>

namespace plantsim::controller::mppi {

void ControlSequence::shift() {
  const Eigen::Index n = vx.size();
  if (n < 2) return;
  vx.head(n - 1) = vx.tail(n - 1).eval();
  wz.head(n - 1) = wz.tail(n - 1).eval();
}

void Rollouts::resize(int batch, int steps) {
  for (Table* t : {&noise_vx, &noise_wz, &vx, &wz, &x, &y, &yaw}) t->resize(batch, steps);
}

void draw_noise(const MppiParams& p, util::RandomStream& rng, Rollouts& r) {
  const auto vx_std = static_cast<float>(p.vx_std), wz_std = static_cast<float>(p.wz_std);
  for (Eigen::Index i = 0; i < r.noise_vx.size(); ++i)
    r.noise_vx.data()[i] = vx_std * static_cast<float>(rng.gaussian());
  for (Eigen::Index i = 0; i < r.noise_wz.size(); ++i)
    r.noise_wz.data()[i] = wz_std * static_cast<float>(rng.gaussian());
}

void roll_out(const MppiParams& p, const ControlSequence& u, const RobotState& state, Rollouts& r) {
  const Eigen::Index batch = r.vx.rows(), steps = r.vx.cols();
  const auto dt = static_cast<float>(p.model_dt);
  // Speeds within their limits, then each step within the accelerations from the one before
  // (the first from the robot's own speed), column by column over the whole batch.
  r.vx = (r.noise_vx.rowwise() + u.vx.transpose())
             .cwiseMax(static_cast<float>(p.vx_min))
             .cwiseMin(static_cast<float>(p.vx_max));
  r.wz = (r.noise_wz.rowwise() + u.wz.transpose())
             .cwiseMax(static_cast<float>(-p.wz_max))
             .cwiseMin(static_cast<float>(p.wz_max));
  const float dv_up = static_cast<float>(p.ax_max) * dt,
              dv_down = static_cast<float>(-p.ax_min) * dt;
  const float dw = static_cast<float>(p.az_max) * dt;
  Eigen::ArrayXf last_v = Eigen::ArrayXf::Constant(batch, state.vx);
  Eigen::ArrayXf last_w = Eigen::ArrayXf::Constant(batch, state.wz);
  for (Eigen::Index t = 0; t < steps; ++t) {
    // Speeding up means a larger |v|; braking, towards zero (Nav2's sign rule).
    auto v = r.vx.col(t);
    const Eigen::ArrayXf forward = (last_v >= 0.0f).cast<float>();
    const Eigen::ArrayXf hi = forward * (last_v + dv_up) + (1.0f - forward) * (last_v + dv_down);
    const Eigen::ArrayXf lo = forward * (last_v - dv_down) + (1.0f - forward) * (last_v - dv_up);
    v = v.cwiseMax(lo).cwiseMin(hi);
    auto w = r.wz.col(t);
    w = w.cwiseMax(last_w - dw).cwiseMin(last_w + dw);
    last_v = v, last_w = w;
  }
  // Poses: each step turns by the step's yaw rate and moves along the heading it starts with.
  Eigen::ArrayXf x = Eigen::ArrayXf::Constant(batch, state.x);
  Eigen::ArrayXf y = Eigen::ArrayXf::Constant(batch, state.y);
  Eigen::ArrayXf yaw = Eigen::ArrayXf::Constant(batch, state.yaw);
  for (Eigen::Index t = 0; t < steps; ++t) {
    x += r.vx.col(t) * yaw.cos() * dt;
    y += r.vx.col(t) * yaw.sin() * dt;
    yaw += r.wz.col(t) * dt;
    r.x.col(t) = x, r.y.col(t) = y, r.yaw.col(t) = yaw;
  }
}

}  // namespace plantsim::controller::mppi
