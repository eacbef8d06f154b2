// The particle filter's likelihood field model: the returns weighed, the tabulated likelihood,
// the set's weights.
#include "robot/particle_field_model.h"

#include <cmath>

#include "robot/global_match.h"
#include "robot/scan_points.h"

namespace plantsim::robot {

ParticleFieldModel::ParticleFieldModel(const worlds::World& map, const ParticleFieldParams& params)
    : p_(params), field_(shared_likelihood_field(map, params.field_resolution_m)) {}

void ParticleFieldModel::take(const LidarScan& scan, int min_returns, double range_sigma_m,
                              bool settled) {
  points_.clear();
  if (valid_returns(scan) < min_returns) return;
  points_ = scan_points(scan, std::max(1, p_.beams));
  hit_sigma_m_ = std::hypot(p_.field_sigma_m, range_sigma_m);
  // A set spread over metres (after a kidnap, a reseed) has particles centimetres apart at best:
  // weighed with the sharp likelihood, the one that happens to sit nearest a partial fit takes
  // all the weight within a few scans, wherever the truth is. Weighed with a wider one until it
  // has settled, it narrows as the evidence builds (AMCL's default sigma_hit is 0.2 m).
  weigh_sigma_m_ = settled ? hit_sigma_m_ : std::hypot(hit_sigma_m_, p_.unsettled_sigma_m);
}

void ParticleFieldModel::tabulate() {
  if (weigh_sigma_m_ == tabulated_sigma_m_) return;
  tabulated_sigma_m_ = weigh_sigma_m_;
  const double reach = field_->reach_m();
  per_reach_squared_ = 1.0 / (reach * reach);
  // log(z_hit exp(-d^2 / 2 s^2) + z_rand) against d^2 up to the field's reach: a table of it,
  // interpolated, in place of an exp and a log per beam and particle (the filter's main cost).
  const double k = 0.5 / (weigh_sigma_m_ * weigh_sigma_m_);
  log_table_.resize(kLogTableSize + 1);
  for (std::size_t i = 0; i <= kLogTableSize; ++i)
    log_table_[i] = std::log(
        p_.z_hit * std::exp(-k * static_cast<double>(i) / kLogTableSize * (reach * reach)) +
        p_.z_rand);
}

double ParticleFieldModel::weigh(std::vector<Particle>& set) {
  if (points_.empty()) return -1;
  const double beams = static_cast<double>(points_.size());
  tabulate();
  std::vector<double> log_w(set.size());
  double best = -INFINITY;
  for (std::size_t n = 0; n < set.size(); ++n) {
    const Particle& q = set[n];
    const double c = std::cos(q.yaw), s = std::sin(q.yaw);
    double l = 0;
    for (const geom::Vec2& e : points_)
      l +=
          beam_log_likelihood(field_->distance({q.x + c * e.x - s * e.y, q.y + s * e.x + c * e.y}));
    log_w[n] = l;
    best = std::max(best, l);
  }
  // Augmented MCL's measure of fit: the prior-weighted mean of each particle's likelihood per
  // beam (a geometric mean, so that it does not depend on how many beams were weighed).
  double fit = 0, total = 0;
  for (std::size_t n = 0; n < set.size(); ++n) {
    fit += set[n].w * std::exp(log_w[n] / beams);
    set[n].w *= std::exp(log_w[n] - best);
    total += set[n].w;
  }
  for (Particle& q : set) q.w = total > 0 && std::isfinite(total) ? q.w / total : 1.0 / set.size();
  return fit;
}

double ParticleFieldModel::log_likelihood(const geom::Pose2& pose) {
  tabulate();
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  double l = 0;
  for (const geom::Vec2& e : points_)
    l += beam_log_likelihood(
        field_->distance({pose.x + c * e.x - s * e.y, pose.y + s * e.x + c * e.y}));
  return l;
}

double ParticleFieldModel::explained_share(const geom::Pose2& pose) const {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  int explained = 0;
  for (const geom::Vec2& e : points_)
    explained +=
        std::fabs(field_->distance({pose.x + c * e.x - s * e.y, pose.y + s * e.x + c * e.y})) <=
        3.0 * hit_sigma_m_;
  return static_cast<double>(explained) / static_cast<double>(points_.size());
}

}  // namespace plantsim::robot
