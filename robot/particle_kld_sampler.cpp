// KLD sampling's count, low-variance resampling and roughening.
#include "robot/particle_kld_sampler.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace plantsim::robot {
namespace {

// KLD sampling's particle count for k occupied bins (Fox 2003, eq. 12): enough that the K-L
// distance between the sampled and the true posterior stays below `error` with the probability
// whose upper quantile is z.
double kld_count(std::size_t k, double error, double z) {
  if (k <= 1) return 0;
  const double km1 = static_cast<double>(k - 1);
  const double a = 2.0 / (9.0 * km1);
  const double c = 1.0 - a + std::sqrt(a) * z;
  return km1 / (2.0 * error) * c * c * c;
}

}  // namespace

std::size_t KldSampler::floor() const {
  return static_cast<std::size_t>(std::max(1, p_.min_particles));
}

std::size_t KldSampler::ceiling() const {
  return std::max(floor(), static_cast<std::size_t>(p_.max_particles));
}

KldSampler::Count KldSampler::count(const std::vector<Particle>& set, double kept_share,
                                    util::RandomStream& rng) const {
  // Copies drawn one by one are a random walk in which a direction the scans leave open (along
  // a lone wall) loses its spread within a few dozen resamplings, and the set reports itself
  // sure of what nothing measured: the draws here only count the bins; the copies are drawn
  // by systematic_draw.
  const WeightedDraw draw(set);
  std::unordered_set<std::uint64_t> bins;
  const std::size_t lo = floor(), hi = ceiling();
  Count n{0, lo};
  while (n.counted < hi) {
    bins.insert(particle_bin_key(particle_bin(draw(set, rng), p_.bin_xy_m, p_.bin_yaw_rad)));
    ++n.counted;
    n.needed = std::clamp(static_cast<std::size_t>(kld_count(bins.size(), p_.kld_error, p_.kld_z)),
                          lo, hi);
    if (static_cast<double>(n.counted) >= kept_share * static_cast<double>(n.needed)) break;
  }
  return n;
}

void KldSampler::systematic_draw(const std::vector<Particle>& set, std::size_t count,
                                 util::RandomStream& rng, std::vector<Particle>& out) {
  out.clear();
  double total = 0;
  for (const Particle& q : set) total += q.w;
  const double step = total / static_cast<double>(std::max<std::size_t>(1, count));
  double next = step * rng.uniform(), cumulative = 0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < count; ++k, next += step) {
    while (n + 1 < set.size() && cumulative + set[n].w < next) cumulative += set[n++].w;
    out.push_back(set[n]);
  }
}

void KldSampler::roughen(std::vector<Particle>& set, util::RandomStream& rng) const {
  // Copies of one particle spread a little, so that repeated weighing at rest does not collapse
  // the set onto a point (it would be sure of itself beyond what the scans say).
  for (Particle& q : set) {
    q.x += particle_normal(rng, p_.jitter_m);
    q.y += particle_normal(rng, p_.jitter_m);
    q.yaw = geom::wrap_angle(q.yaw + particle_normal(rng, p_.jitter_rad));
  }
}

}  // namespace plantsim::robot
