// Sampling and integrating MPPI's control sequences (see the header).
#include "controller/mppi/rollouts.h"

#include <algorithm>
#include <cmath>

namespace plantsim::controller::mppi {
namespace {

constexpr float kTwoPi = 6.28318530717958647f;

/// Fills `out` with N(0, std^2) draws: pairs r cos(t), r sin(t) from uniforms u1 in (0, 1] and
/// u2 in [0, 1) (24 bits each from one 64-bit draw), the logarithm and the trigonometry
/// vectorised over the column.
void normal_column(util::RandomStream& rng, float std_dev, Eigen::Ref<Eigen::ArrayXf> out,
                   Eigen::ArrayXf& u1, Eigen::ArrayXf& u2) {
  const Eigen::Index n = out.size(), pairs = (n + 1) / 2;
  u1.resize(pairs), u2.resize(pairs);
  for (Eigen::Index i = 0; i < pairs; ++i) {
    const std::uint64_t b = rng.bits();
    u1(i) = static_cast<float>((b >> 40) + 1) * 0x1p-24f;
    u2(i) = static_cast<float>((b >> 8) & 0xffffffu) * 0x1p-24f;
  }
  u1 = std_dev * (-2.0f * u1.log()).sqrt();
  u2 *= kTwoPi;
  out.head(n / 2) = u1.head(n / 2) * u2.head(n / 2).cos();
  out.tail(n - n / 2) = u1.head(n - n / 2) * u2.head(n - n / 2).sin();
}

}  // namespace

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
  Eigen::ArrayXf u1, u2;
  for (Eigen::Index t = 0; t < r.noise_vx.cols(); ++t) {
    normal_column(rng, static_cast<float>(p.vx_std), r.noise_vx.col(t), u1, u2);
    normal_column(rng, static_cast<float>(p.wz_std), r.noise_wz.col(t), u1, u2);
  }
}

void roll_out(const MppiParams& p, const ControlSequence& u, const RobotState& state, Rollouts& r) {
  const Eigen::Index batch = r.vx.rows(), steps = r.vx.cols();
  const auto dt = static_cast<float>(p.model_dt);
  const auto vx_min = static_cast<float>(p.vx_min), vx_max = static_cast<float>(p.vx_max);
  const auto wz_max = static_cast<float>(p.wz_max);
  const float dv_up = static_cast<float>(p.ax_max) * dt,
              dv_down = static_cast<float>(-p.ax_min) * dt;
  const float dw = static_cast<float>(p.az_max) * dt;
  // The heading as its cosine and sine, turned step by step by the first terms of the small
  // turn's cosine and sine (below 0.1 rad a step at Nav2's limits; exact in single precision up
  // to 0.5 rad): no trigonometry per pose. The step before the first is the robot's own state.
  Eigen::ArrayXf c = Eigen::ArrayXf::Constant(batch, std::cos(state.yaw));
  Eigen::ArrayXf s = Eigen::ArrayXf::Constant(batch, std::sin(state.yaw));
  Eigen::ArrayXf start(batch * 5);
  start << Eigen::ArrayXf::Constant(batch, state.vx), Eigen::ArrayXf::Constant(batch, state.wz),
      Eigen::ArrayXf::Constant(batch, state.x), Eigen::ArrayXf::Constant(batch, state.y),
      Eigen::ArrayXf::Constant(batch, state.yaw);
  for (Eigen::Index t = 0; t < steps; ++t) {
    const auto before = [&](Table& table, int k) -> const float* {
      return t > 0 ? table.col(t - 1).data() : start.data() + k * batch;
    };
    const float* __restrict lv = before(r.vx, 0);
    const float* __restrict lw = before(r.wz, 1);
    const float* __restrict px = before(r.x, 2);
    const float* __restrict py = before(r.y, 3);
    const float* __restrict pyaw = before(r.yaw, 4);
    const float* __restrict nv = r.noise_vx.col(t).data();
    const float* __restrict nw = r.noise_wz.col(t).data();
    float* __restrict v = r.vx.col(t).data();
    float* __restrict w = r.wz.col(t).data();
    float* __restrict x = r.x.col(t).data();
    float* __restrict y = r.y.col(t).data();
    float* __restrict yaw = r.yaw.col(t).data();
    float* __restrict cs = c.data();
    float* __restrict sn = s.data();
    const float uv = u.vx(t), uw = u.wz(t);
    for (Eigen::Index b = 0; b < batch; ++b) {
      // Speeds within their limits, then within the accelerations from the step before;
      // speeding up means a larger |v|, braking towards zero (Nav2's sign rule).
      const bool forward = lv[b] >= 0.0f;
      const float hi = lv[b] + (forward ? dv_up : dv_down);
      const float lo = lv[b] - (forward ? dv_down : dv_up);
      const float vb = std::min(std::max(std::min(std::max(nv[b] + uv, vx_min), vx_max), lo), hi);
      const float wb = std::min(
          std::max(std::min(std::max(nw[b] + uw, -wz_max), wz_max), lw[b] - dw), lw[b] + dw);
      v[b] = vb, w[b] = wb;
      // Each step moves along the heading it starts with, then turns by the step's yaw rate.
      x[b] = px[b] + vb * cs[b] * dt;
      y[b] = py[b] + vb * sn[b] * dt;
      yaw[b] = pyaw[b] + wb * dt;
      const float a = wb * dt, a2 = a * a;
      const float rc = 1.0f - a2 * (0.5f - a2 * (1.0f / 24.0f - a2 * (1.0f / 720.0f)));
      const float rs =
          a * (1.0f - a2 * (1.0f / 6.0f - a2 * (1.0f / 120.0f - a2 * (1.0f / 5040.0f))));
      const float cb = cs[b];
      cs[b] = cb * rc - sn[b] * rs;
      sn[b] = sn[b] * rc + cb * rs;
    }
  }
}

}  // namespace plantsim::controller::mppi
