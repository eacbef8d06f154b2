// The best cluster's mean and the set's covariance about it.
#include "robot/particle_clusters.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <unordered_map>

namespace plantsim::robot {

ParticleEstimate cluster_estimate(const std::vector<Particle>& set, double bin_xy_m,
                                  double bin_yaw_rad) {
  // The heaviest bin, and the cluster of particles in it and its neighbours.
  std::unordered_map<std::uint64_t, double> weight;
  const Particle* heaviest = &set.front();
  double heaviest_w = -1;
  for (const Particle& q : set) {
    const double w = weight[particle_bin_key(particle_bin(q, bin_xy_m, bin_yaw_rad))] += q.w;
    if (w > heaviest_w) {
      heaviest_w = w;
      heaviest = &q;
    }
  }
  const ParticleBin top = particle_bin(*heaviest, bin_xy_m, bin_yaw_rad);
  const std::int64_t turns = static_cast<std::int64_t>(std::ceil(2.0 * M_PI / bin_yaw_rad));
  double w = 0, x = 0, y = 0, c = 0, s = 0;
  for (const Particle& q : set) {
    const ParticleBin b = particle_bin(q, bin_xy_m, bin_yaw_rad);
    const std::int64_t dt = ((b.t - top.t) % turns + turns) % turns;
    if (std::abs(b.x - top.x) > 1 || std::abs(b.y - top.y) > 1 || (dt > 1 && dt < turns - 1))
      continue;
    w += q.w;
    x += q.w * q.x;
    y += q.w * q.y;
    c += q.w * std::cos(q.yaw);
    s += q.w * std::sin(q.yaw);
  }
  ParticleEstimate out;
  out.pose = {x / w, y / w, std::atan2(s, c)};
  // The whole set about it: other live hypotheses widen it.
  for (const Particle& q : set) {
    const Eigen::Vector3d d(q.x - out.pose.x, q.y - out.pose.y,
                            geom::wrap_angle(q.yaw - out.pose.yaw));
    out.covariance += q.w * d * d.transpose();
  }
  out.covariance.diagonal().array() += 1e-8;
  return out;
}

}  // namespace plantsim::robot
