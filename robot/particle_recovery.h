// The particle filter's recovery (augmented MCL, Thrun et al. ch. 8.3; AMCL's w_slow / w_fast):
// owns the long- and short-term averages of how well the set fits the scans, the share of
// particles drawn anew that they ask for, and the drawing of those fresh particles about the
// places a global match found (sensor resetting, Lenser and Veloso 2000), each with its
// importance weight. Where the places come from: particle_place_search.h.
#pragma once

#include <cstddef>
#include <vector>

#include "robot/particle_set.h"
#include "util/random_stream.h"

namespace plantsim::robot {

struct ParticleRecoveryParams {
  double alpha_slow = 0.001;  ///< augmented MCL's long- and short-term averages of the weight
  double alpha_fast = 0.1;
  double reseed_fraction = 0.5;  ///< at least this share is drawn anew when the map contradicts
};

class ParticleRecovery {
 public:
  explicit ParticleRecovery(const ParticleRecoveryParams& params) : p_(params) {}
  const ParticleRecoveryParams& params() const { return p_; }

  /// One weighing's fit (the set's mean per-beam likelihood) into the averages.
  void add_fit(double fit);
  /// The share to draw anew about the places found: what the averages ask for, at least
  /// reseed_fraction, at most 0.9.
  double fresh_share() const;

  /// Appends to `set` the fresh particles about `places`: `fresh` of `needed` (at least 30 a
  /// place, within the room `ceiling` leaves), split evenly, each drawn over its place's spread
  /// (`fallback_sd` where it has none) with a bias from the set's (`bias`, `bias_var`).
  /// Returns their inverse densities (importance weights before scaling), in order.
  static std::vector<double> inject(const std::vector<ParticlePlace>& places, double fresh,
                                    std::size_t needed, std::size_t ceiling,
                                    const Eigen::Vector3d& fallback_sd, double bias,
                                    double bias_var, util::RandomStream& rng,
                                    std::vector<Particle>& set);
  /// The weights after a resampling: the `kept` first particles alike, the fresh ones after them
  /// by their importance weights, scaled so that the fresh share keeps its share of the weight.
  static void weigh_resampled(std::vector<Particle>& set, std::size_t kept,
                              const std::vector<double>& inverse_density);

 private:
  ParticleRecoveryParams p_;
  double w_slow_ = 0, w_fast_ = 0;
};

}  // namespace plantsim::robot
