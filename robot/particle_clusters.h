// The particle filter's estimate from its set (AMCL's cluster statistics): the heaviest
// histogram bin and its neighbours make the best cluster, whose weighted mean is the estimate;
// the covariance is the whole set's about it, so that two live hypotheses make it wide. Owns no
// state.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/vec2.h"
#include "robot/particle_set.h"

namespace plantsim::robot {

struct ParticleEstimate {
  geom::Pose2 pose;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
};

/// The estimate of a non-empty set whose weights sum to one, over bins of `bin_xy_m` by
/// `bin_yaw_rad` (KLD sampling's).
ParticleEstimate cluster_estimate(const std::vector<Particle>& set, double bin_xy_m,
                                  double bin_yaw_rad);

}  // namespace plantsim::robot
