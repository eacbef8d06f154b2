// The particle filter's sensor model (AMCL's likelihood field model): owns the scan's returns
// it weighs by, the likelihood's sigma and its tabulated logarithm, and the signed distance
// field of the map it looks returns up in (likelihood_field.h, shared among episodes). Weighs
// the set, and scores or checks any one pose by the same returns.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

#include "geometry/vec2.h"
#include "robot/likelihood_field.h"
#include "robot/particle_set.h"
#include "robot/readings.h"
#include "worlds/world.h"

namespace plantsim::robot {

struct ParticleFieldParams {
  int beams = 40;  ///< beams per scan in the weights, spread evenly over the valid ones
  /// A return d from the nearest mapped surface scores z_hit exp(-d^2 / 2 s^2) + z_rand (z_rand:
  /// what the map does not explain, a box, a person), with s^2 the range noise the filter uses
  /// (told or learnt) plus field_sigma_m^2 (the map's error and the set's own spread).
  double z_hit = 0.9;
  double z_rand = 0.05;
  double field_sigma_m = 0.05;
  /// While the filter is not `ok` the weights use a likelihood this much wider (added in
  /// quadrature), so that a set spread over metres narrows as evidence builds, not at once.
  double unsettled_sigma_m = 0.2;
  double field_resolution_m = 0.05;  ///< the likelihood field's cells (likelihood_field.h)
};

class ParticleFieldModel {
 public:
  ParticleFieldModel(const worlds::World& map, const ParticleFieldParams& params);

  /// The scan's returns to weigh by, in the robot frame (none when fewer than `min_returns` are
  /// valid), with the range noise the filter uses; `settled`: the filter is ok (else the wider
  /// likelihood).
  void take(const LidarScan& scan, int min_returns, double range_sigma_m, bool settled);
  const std::vector<geom::Vec2>& points() const { return points_; }
  const LikelihoodField& field() const { return *field_; }

  /// Weighs the set by the returns (weights normalised); returns the weighted mean per-beam
  /// likelihood (augmented MCL's measure of fit), or -1 when there are none.
  double weigh(std::vector<Particle>& set);
  /// The returns' summed log-likelihood at `pose`.
  double log_likelihood(const geom::Pose2& pose);
  /// Share of the returns within three sigmas of a mapped surface from `pose`.
  double explained_share(const geom::Pose2& pose) const;

 private:
  void tabulate();
  /// A return's log-likelihood at distance d from the nearest mapped surface (inline: asked for
  /// every beam of every particle).
  double beam_log_likelihood(double d) const {
    const double u = std::min(1.0, d * d * per_reach_squared_) * kLogTableSize;
    const std::size_t i = std::min(static_cast<std::size_t>(u), kLogTableSize - 1);
    const double f = u - static_cast<double>(i);
    return log_table_[i] + f * (log_table_[i + 1] - log_table_[i]);
  }

  ParticleFieldParams p_;
  std::shared_ptr<const LikelihoodField> field_;  // shared among episodes on the same map
  std::vector<geom::Vec2> points_;                // the weighed beams' returns in the robot frame
  double hit_sigma_m_ = 0;                        // the likelihood's sigma for them
  double weigh_sigma_m_ = 0;  // and the one they are weighed with (wider while unsettled)
  static constexpr std::size_t kLogTableSize = 4096;
  std::vector<double> log_table_;  // log-likelihood against the squared distance
  double tabulated_sigma_m_ = -1;
  double per_reach_squared_ = 1;  // 1 / (the field's reach)^2, the table's scale
};

}  // namespace plantsim::robot
