// The particle filter's common vocabulary (particle_localizer.h and its parts): a particle, a
// place a global match found, the histogram bins KLD sampling and the clusters share, draws by
// weight and the filter's normal draw. Owns no state.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/vec2.h"
#include "util/random_stream.h"

namespace plantsim::robot {

/// A pose and the gyro bias that particle assumes: a bias error turns the heading steadily,
/// so each particle carries its own and the scans choose among them (as the EKF's state does).
struct Particle {
  double x, y, yaw, bias, w;
};

/// A place a global match finds for a scan: the pose, its score and the spread of the poses
/// about it that fit about as well (ScanMatch::spread).
struct ParticlePlace {
  geom::Pose2 pose;
  double score = 0;
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
};

/// sigma times a standard normal draw, or 0 (and no draw) when sigma is not positive.
inline double particle_normal(util::RandomStream& rng, double sigma) {
  return sigma > 0 ? sigma * rng.gaussian() : 0;
}

/// A particle's histogram bin: cells of bin_xy_m by bin_xy_m by bin_yaw_rad.
struct ParticleBin {
  std::int64_t x, y, t;
};

inline ParticleBin particle_bin(const Particle& q, double bin_xy_m, double bin_yaw_rad) {
  return {static_cast<std::int64_t>(std::floor(q.x / bin_xy_m)),
          static_cast<std::int64_t>(std::floor(q.y / bin_xy_m)),
          static_cast<std::int64_t>(std::floor((geom::wrap_angle(q.yaw) + M_PI) / bin_yaw_rad))};
}

inline std::uint64_t particle_bin_key(const ParticleBin& b) {
  constexpr std::uint64_t kMask = (1u << 21) - 1;
  return ((static_cast<std::uint64_t>(b.x) & kMask) << 42) |
         ((static_cast<std::uint64_t>(b.y) & kMask) << 21) |
         (static_cast<std::uint64_t>(b.t) & kMask);
}

/// Particles drawn with probability proportional to their weights (multinomial resampling).
class WeightedDraw {
 public:
  explicit WeightedDraw(const std::vector<Particle>& set) : cumulative_(set.size()) {
    double sum = 0;
    for (std::size_t n = 0; n < set.size(); ++n) cumulative_[n] = sum += set[n].w;
    sum_ = sum;
  }
  const Particle& operator()(const std::vector<Particle>& set, util::RandomStream& rng) const {
    const auto at = std::lower_bound(cumulative_.begin(), cumulative_.end(), sum_ * rng.uniform());
    return set[std::min<std::size_t>(static_cast<std::size_t>(at - cumulative_.begin()),
                                     set.size() - 1)];
  }

 private:
  std::vector<double> cumulative_;
  double sum_ = 0;
};

}  // namespace plantsim::robot
