// MPPI's samples: control sequences drawn as noise around the last optimum, passed through the
// differential drive's limits (speeds, then accelerations step by step, as
// nav2_mppi_controller's DiffDriveMotionModel does), and integrated into poses. One row per
// sample, one column per time step, in single precision as Nav2 computes them; stored column
// by column, so that each step is one contiguous vector over the whole batch.
#pragma once

#include <Eigen/Core>

#include "controller/mppi/mppi_params.h"
#include "util/random_stream.h"

namespace plantsim::controller::mppi {

using Table = Eigen::Array<float, Eigen::Dynamic, Eigen::Dynamic>;

/// The optimum so far: one command per time step.
struct ControlSequence {
  Eigen::ArrayXf vx, wz;
  explicit ControlSequence(int steps = 0) : vx(Eigen::ArrayXf::Zero(steps)), wz(vx) {}
  /// One step on: the first command was sent; the last is repeated (Nav2's shift).
  void shift();
};

/// Where the robot is and how it moves now (its estimate).
struct RobotState {
  float x = 0, y = 0, yaw = 0;
  float vx = 0, wz = 0;
};

struct Rollouts {
  Table noise_vx, noise_wz;  ///< the draws, before the limits
  Table vx, wz;              ///< the commands each sample drives, after the limits
  Table x, y, yaw;           ///< the pose after each step
  void resize(int batch, int steps);
};

/// Draws the noise for every sample and step (batch x steps normal draws per control), by the
/// Box-Muller transform over whole columns: two draws from each 64 bits of the stream.
void draw_noise(const MppiParams& p, util::RandomStream& rng, Rollouts& r);

/// The commands (sequence + noise, limited) and the poses they reach from `state`.
void roll_out(const MppiParams& p, const ControlSequence& u, const RobotState& state, Rollouts& r);

}  // namespace plantsim::controller::mppi
