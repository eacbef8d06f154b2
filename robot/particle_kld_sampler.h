// The particle filter's resampler (AMCL's pf_update_resample with KLD sampling, Fox 2003): owns
// the bounds on the set's size, the histogram bins the count is taken over (the clusters use the
// same bins) and the roughening of the copies. How many particles the weights call for, those
// drawn by low-variance resampling, and each copy spread a little.
#pragma once

#include <cstddef>
#include <vector>

#include "robot/particle_set.h"
#include "util/random_stream.h"

namespace plantsim::robot {

struct KldSamplerParams {
  int min_particles = 200;   ///< KLD sampling's floor (AMCL: 500)
  int max_particles = 2000;  ///< and its ceiling (AMCL: 2000)
  double kld_error = 0.05;   ///< bound on the K-L distance to the true posterior (AMCL: 0.01)
  double kld_z = 2.33;       ///< its upper quantile (0.99)
  double bin_xy_m = 0.5;     ///< histogram bins for KLD sampling and the clusters
  double bin_yaw_rad = 0.175;
  double jitter_m = 0.003;    ///< roughening: each resampled copy spread by this (keeps the set
  double jitter_rad = 0.003;  ///< diverse; resampling happens only after weighing)
};

class KldSampler {
 public:
  explicit KldSampler(const KldSamplerParams& params) : p_(params) {}
  const KldSamplerParams& params() const { return p_; }

  /// The set's floor and ceiling (at least one particle).
  std::size_t floor() const;
  std::size_t ceiling() const;

  struct Count {
    std::size_t counted = 0;  ///< particles to keep
    std::size_t needed = 0;   ///< KLD sampling's count for the whole set
  };
  /// KLD sampling's count for the bins that draws by the weights fill, drawn until `kept_share`
  /// of it is reached (the rest left to fresh particles).
  Count count(const std::vector<Particle>& set, double kept_share, util::RandomStream& rng) const;
  /// `out` = `count` copies of the set's particles, drawn by low-variance (systematic)
  /// resampling: one random offset for all.
  static void systematic_draw(const std::vector<Particle>& set, std::size_t count,
                              util::RandomStream& rng, std::vector<Particle>& out);
  /// Roughening: each particle spread by the jitter.
  void roughen(std::vector<Particle>& set, util::RandomStream& rng) const;

 private:
  KldSamplerParams p_;
};

}  // namespace plantsim::robot
