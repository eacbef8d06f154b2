// Augmented MCL's averages and the fresh particles drawn about the places a scan fits.
#include "robot/particle_recovery.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace plantsim::robot {
namespace {

// A place's pose and spread as a normal distribution to draw from and to evaluate (the spread's
// Cholesky factor; a spread that has none is replaced by `fallback_sd` on its diagonal).
class PlaceSpread {
 public:
  PlaceSpread(const ParticlePlace& place, const Eigen::Vector3d& fallback_sd) : mean_(place.pose) {
    const Eigen::LLT<Eigen::Matrix3d> root(place.spread);
    l_ = root.info() == Eigen::Success ? Eigen::Matrix3d(root.matrixL())
                                       : Eigen::Matrix3d(fallback_sd.asDiagonal());
    log_norm_ = -std::log(std::fabs(l_.diagonal().prod()));
  }
  template <class UnitNormal>
  geom::Pose2 draw(UnitNormal&& unit) const {
    const Eigen::Vector3d d = l_ * Eigen::Vector3d(unit(), unit(), unit());
    return {mean_.x + d.x(), mean_.y + d.y(), geom::wrap_angle(mean_.yaw + d.z())};
  }
  /// The density at `x`, up to a constant common to every place.
  double density(const geom::Pose2& x) const {
    const Eigen::Vector3d d(x.x - mean_.x, x.y - mean_.y, geom::wrap_angle(x.yaw - mean_.yaw));
    const Eigen::Vector3d z = l_.triangularView<Eigen::Lower>().solve(d);
    return std::exp(log_norm_ - 0.5 * z.squaredNorm());
  }

 private:
  geom::Pose2 mean_;
  Eigen::Matrix3d l_;
  double log_norm_ = 0;
};

}  // namespace

void ParticleRecovery::add_fit(double fit) {
  if (w_slow_ <= 0) w_slow_ = w_fast_ = fit;
  w_slow_ += p_.alpha_slow * (fit - w_slow_);
  w_fast_ += p_.alpha_fast * (fit - w_fast_);
}

double ParticleRecovery::fresh_share() const {
  const double demand = w_slow_ > 0 ? 1.0 - w_fast_ / w_slow_ : 0.0;
  return std::clamp(std::max(demand, p_.reseed_fraction), 0.0, 0.9);
}

std::vector<double> ParticleRecovery::inject(const std::vector<ParticlePlace>& places, double fresh,
                                             std::size_t needed, std::size_t ceiling,
                                             const Eigen::Vector3d& fallback_sd, double bias,
                                             double bias_var, util::RandomStream& rng,
                                             std::vector<Particle>& set) {
  // Each drawn over its place's spread (Olson's covariance of the near-best poses): along a lone
  // wall, where the scan leaves the place open, the fresh particles cover the wall rather than
  // points a metre apart.
  std::vector<double> inverse_density;
  if (places.empty()) return inverse_density;
  const std::size_t room = ceiling > set.size() ? ceiling - set.size() : 0;
  const std::size_t each = std::min(
      room / places.size(),
      std::max<std::size_t>(
          30, static_cast<std::size_t>(fresh * static_cast<double>(needed)) / places.size()));
  std::vector<PlaceSpread> spreads;
  for (const ParticlePlace& place : places) spreads.emplace_back(place, fallback_sd);
  for (const PlaceSpread& place : spreads)
    for (std::size_t k = 0; k < each; ++k) {
      const geom::Pose2 x = place.draw([&] { return particle_normal(rng, 1.0); });
      set.push_back({x.x, x.y, x.yaw, bias + particle_normal(rng, std::sqrt(bias_var)), 1.0});
      // Importance weight: one over the density the fresh particles were drawn from (the
      // mixture of the places), so that a place drawn densely (a tight match) does not win
      // over one drawn thinly (a match open along a wall) by numbers alone.
      double density = 0;
      for (const PlaceSpread& other : spreads) density += other.density(x);
      inverse_density.push_back(1.0 / std::max(density, 1e-300));
    }
  return inverse_density;
}

void ParticleRecovery::weigh_resampled(std::vector<Particle>& set, std::size_t kept,
                                       const std::vector<double>& inverse_density) {
  double mean_inverse = 0;
  for (double v : inverse_density) mean_inverse += v / static_cast<double>(inverse_density.size());
  const double n = static_cast<double>(set.size());
  for (std::size_t k = 0; k < set.size(); ++k)
    set[k].w = (k < kept ? 1.0 : inverse_density[k - kept] / mean_inverse) / n;
}

}  // namespace plantsim::robot
