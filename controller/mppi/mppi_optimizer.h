// Model predictive path integral control (Williams et al., "Information-theoretic MPC", 2017)
// in the manner of nav2_mppi_controller: each cycle draws batch_size noised control sequences
// around the last optimum, rolls them through the diff-drive model, scores them with the
// critics, and takes the softmax-weighted mean of the samples (temperature, with the gamma
// control cost) as the new optimum; the first command is sent and the sequence shifted.
#pragma once

#include <cstdint>
#include <vector>

#include "controller/diff_drive.h"
#include "controller/mppi/critics.h"

namespace plantsim::controller::mppi {

/// A cycle's question: the robot's estimate, its plan and what it knows of the obstacles.
struct MppiQuery {
  RobotState state;
  geom::Pose2 goal;  ///< the plan's end and the heading wanted there
  const ClearanceGrid* clearance = nullptr;
  float robot_radius_m = 0.2f;
};

class MppiOptimizer {
 public:
  MppiOptimizer(MppiParams params, CriticParams critics, std::uint64_t seed);

  /// A new plan (a polyline in the map frame): resampled every `path_spacing_m`.
  void set_path(const std::vector<geom::Vec2>& plan, double path_spacing_m = 0.05);

  /// One control cycle: the command to send now.
  Twist step(const MppiQuery& q);

  /// The last cycle's optimum as poses (for the replay) and a few of its samples.
  const std::vector<geom::Pose2>& optimal_trajectory() const { return optimal_; }
  std::vector<std::vector<geom::Pose2>> sampled_trajectories(int count) const;
  const ControlSequence& control_sequence() const { return u_; }

 private:
  void prune_path(const RobotState& s);
  void optimise_once(const MppiQuery& q);
  void remember_optimum(const MppiQuery& q);

  MppiParams p_;
  CriticParams c_;
  util::RandomStream rng_;
  ControlSequence u_;
  Rollouts r_;
  Costs costs_;
  Eigen::ArrayXf weights_;        ///< the softmax over the samples' costs
  std::vector<geom::Vec2> path_;  ///< the whole plan, resampled
  std::vector<float> path_s_;
  std::size_t progress_ = 0;        ///< the plan's point nearest the robot, never back
  std::vector<geom::Vec2> window_;  ///< the plan the critics see: prune_distance of it
  std::vector<float> window_s_;
  std::vector<geom::Pose2> optimal_;
};

}  // namespace plantsim::controller::mppi
