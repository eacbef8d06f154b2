// The particle filter's cycle: the motion model, the likelihood-field weights, KLD resampling
// with sensor resetting, the clustered estimate and its health.
#include "robot/particle_localizer.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "robot/median_spread.h"
#include "robot/place_refinement.h"
#include "robot/scan_points.h"

namespace plantsim::robot {
namespace {

double sq(double v) { return v * v; }

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

struct Bin {
  std::int64_t x, y, t;
};

Bin bin_of(const ParticleLocalizer::Particle& q, const ParticleParams& p) {
  return {static_cast<std::int64_t>(std::floor(q.x / p.bin_xy_m)),
          static_cast<std::int64_t>(std::floor(q.y / p.bin_xy_m)),
          static_cast<std::int64_t>(std::floor((geom::wrap_angle(q.yaw) + M_PI) / p.bin_yaw_rad))};
}

std::uint64_t key_of(const Bin& b) {
  constexpr std::uint64_t kMask = (1u << 21) - 1;
  return ((static_cast<std::uint64_t>(b.x) & kMask) << 42) |
         ((static_cast<std::uint64_t>(b.y) & kMask) << 21) |
         (static_cast<std::uint64_t>(b.t) & kMask);
}

// Particles drawn with probability proportional to their weights (multinomial resampling).
class WeightedDraw {
 public:
  explicit WeightedDraw(const std::vector<ParticleLocalizer::Particle>& set)
      : cumulative_(set.size()) {
    double sum = 0;
    for (std::size_t n = 0; n < set.size(); ++n) cumulative_[n] = sum += set[n].w;
    sum_ = sum;
  }
  const ParticleLocalizer::Particle& operator()(const std::vector<ParticleLocalizer::Particle>& set,
                                                util::RandomStream& rng) const {
    const auto at = std::lower_bound(cumulative_.begin(), cumulative_.end(), sum_ * rng.uniform());
    return set[std::min<std::size_t>(static_cast<std::size_t>(at - cumulative_.begin()),
                                     set.size() - 1)];
  }

 private:
  std::vector<double> cumulative_;
  double sum_ = 0;
};

// A place's pose and spread as a normal distribution to draw from and to evaluate (the spread's
// Cholesky factor; a spread that has none is replaced by `fallback_sd` on its diagonal).
class PlaceSpread {
 public:
  PlaceSpread(const ParticleLocalizer::Place& place, const Eigen::Vector3d& fallback_sd)
      : mean_(place.pose) {
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

// The global matches for reseeding search all headings in tiles: each may score more candidates
// than a local relocalisation does.
ScanMatcherParams reseed_matcher(ScanMatcherParams m) {
  m.max_candidates = std::max(m.max_candidates, 120'000L);
  // Its coarse rotation steps move a return 20 m away by up to 17 cm, so the true place may
  // score well below what it scores exactly: places are taken at a lower score, then polished
  // (matched again in a narrow window at full resolution) and judged by min_score.
  m.min_score *= 0.6;
  return m;
}

// Robust variance of residuals: the median absolute deviation's, scaled for a normal.
double robust_variance(std::vector<double>& r) { return sq(1.4826 * median_spread(r).mad); }

}  // namespace

ParticleLocalizer::ParticleLocalizer(const worlds::World& map, const MapRaycaster& raycaster,
                                     const EkfParams& motion, const GlobalMatchParams& global,
                                     const ParticleParams& params)
    : raycaster_(raycaster),
      motion_(motion),
      global_(global),
      p_(params),
      map_(map),
      field_(shared_likelihood_field(map, params.field_resolution_m)),
      rng_(static_cast<std::uint64_t>(params.seed) ^ 0x7061727469636c65ULL),  // "particle"
      range_learnt_(motion.range_learning_rate),
      gyro_learnt_(motion.gyro_learning_rate, motion.gyro_min_samples) {
  // As AMCL starts: the prior drawn at the ceiling, KLD sampling choosing fewer at the first
  // resampling. (Started at the floor, 200 draws of a three-dimensional prior left the truth
  // 2.5 sigmas out with no particle near it, and the first sharp weighing collapsed the set 12 cm
  // off with a spread of 5 mm.)
  const int n = std::max({1, p_.min_particles, p_.max_particles});
  set_.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    set_.push_back({map.start.x + normal(motion.initial_position_sigma_m),
                    map.start.y + normal(motion.initial_position_sigma_m),
                    geom::wrap_angle(map.start.yaw + normal(motion.initial_yaw_sigma_rad)),
                    normal(motion.initial_bias_sigma_radps), 1.0 / n});
  bias_moments();
  summarise();
  update_health();
}

double ParticleLocalizer::normal(double sigma) { return sigma > 0 ? sigma * rng_.gaussian() : 0; }

void ParticleLocalizer::predict(double distance_m, double gyro_yaw_rate_radps, double dt_s) {
  if (dt_s <= 0) return;
  gyro_learnt_.reading();
  const double turn = (gyro_yaw_rate_radps - bias_) * dt_s;
  const double mid = pending_.delta.yaw + 0.5 * turn;
  pending_.delta.x += distance_m * std::cos(mid);
  pending_.delta.y += distance_m * std::sin(mid);
  pending_.delta.yaw += turn;
  pending_.moved_m += std::fabs(distance_m);
  pending_.turned_rad += std::fabs(turn);
  const double gyro_sigma =
      motion_.learn_noise ? gyro_learnt_.sigma(motion_.gyro_noise_radps) : motion_.gyro_noise_radps;
  pending_.gyro_var += sq(gyro_sigma * dt_s);
  pending_.time_s += dt_s;
  update_health();
}

void ParticleLocalizer::standstill(double gyro_yaw_rate_radps, double dt_s) {
  if (dt_s <= 0) return;
  const double sigma =
      motion_.learn_noise ? gyro_learnt_.sigma(motion_.gyro_noise_radps) : motion_.gyro_noise_radps;
  if (!at_rest(gyro_yaw_rate_radps - bias_, sigma * sigma + bias_var_))
    return predict(0.0, gyro_yaw_rate_radps, dt_s);
  gyro_learnt_.reading();
  apply_motion();  // the motion so far under the biases as they were
  if (!motion_.learn_noise) {
    update_bias(gyro_yaw_rate_radps);
  } else {
    gyro_learnt_.at_rest(gyro_yaw_rate_radps);  // the readings wait until the noise is learnt
    for (const double z : gyro_learnt_.take_readings()) update_bias(z);
  }
  update_health();
}

void ParticleLocalizer::update_bias(double gyro_yaw_rate_radps) {
  // At rest the gyro reads the bias plus white noise: the Kalman update of the set's bias, each
  // particle's moved to the posterior by the ensemble square-root update (its deviation from the
  // mean shrunk as the variance is), so that the set keeps its spread's shape.
  const double r = sq(motion_.learn_noise ? gyro_learnt_.sigma(motion_.gyro_noise_radps)
                                          : motion_.gyro_noise_radps);
  bias_moments();
  const double k = bias_var_ / (bias_var_ + r);
  if (!std::isfinite(k) || bias_var_ <= 0) return;
  const double mean = bias_ + k * (gyro_yaw_rate_radps - bias_);
  const double shrink = std::sqrt(1.0 - k);
  for (Particle& q : set_) q.bias = mean + shrink * (q.bias - bias_);
  bias_ = mean;
  bias_var_ *= 1.0 - k;
}

void ParticleLocalizer::bias_moments() {
  double mean = 0;
  for (const Particle& q : set_) mean += q.w * q.bias;
  double var = 0;
  for (const Particle& q : set_) var += q.w * sq(q.bias - mean);
  bias_ = mean;
  bias_var_ = var;
}

ParticleLocalizer::Pending ParticleLocalizer::chain(const Pending& first, const Pending& then) {
  Pending out = then;
  out.delta = geom::compose(first.delta, then.delta);
  out.moved_m += first.moved_m;
  out.turned_rad += first.turned_rad;
  out.gyro_var += first.gyro_var;
  out.time_s += first.time_s;
  return out;
}

bool ParticleLocalizer::may_defer() const {
  return health_ == LocalizationHealth::kOk && failed_matches_ == 0 && !confirm_.active &&
         !nudge_ && handover_.empty() &&
         since_weigh_m_ + deferred_.moved_m + pending_.moved_m < p_.update_min_m &&
         since_weigh_rad_ + deferred_.turned_rad + pending_.turned_rad < p_.update_min_rad;
}

void ParticleLocalizer::defer_motion() {
  const geom::Pose2 moved = geom::compose(estimate_, pending_.delta);
  estimate_ = {moved.x, moved.y, geom::wrap_angle(moved.yaw)};
  deferred_ = chain(deferred_, pending_);
  pending_ = {};
}

void ParticleLocalizer::apply_motion() {
  const Pending m = deferred_.time_s > 0 ? chain(deferred_, pending_) : pending_;
  pending_ = deferred_ = {};
  if (m.time_s <= 0) return;
  since_weigh_m_ += m.moved_m;
  since_weigh_rad_ += m.turned_rad;
  confirm_.turned_rad += m.turned_rad;
  confirm_.moved_m += m.moved_m;
  places_.move(m.delta);
  // As the EKF's model: travel noise along, skid across while turning on the move, the gyro's
  // white noise; each particle turns by its own bias (the delta was summed under the set's mean),
  // and its bias walks.
  const double along = motion_.distance_noise * m.moved_m;
  const double across = motion_.lateral_noise * std::min(m.turned_rad, m.moved_m / 0.1);
  const double yaw = std::sqrt(m.gyro_var);
  const double walk = motion_.bias_walk_radps_per_sqrt_s * std::sqrt(m.time_s);
  const double length = std::hypot(m.delta.x, m.delta.y);
  const geom::Vec2 u =
      length > 1e-9 ? geom::Vec2{m.delta.x / length, m.delta.y / length} : geom::Vec2{1.0, 0.0};
  for (Particle& q : set_) {
    const double a = normal(along), c = normal(across);
    const geom::Pose2 d{m.delta.x + a * u.x - c * u.y, m.delta.y + a * u.y + c * u.x,
                        m.delta.yaw - (q.bias - bias_) * m.time_s + normal(yaw)};
    q.bias += normal(walk);
    const geom::Pose2 moved = geom::compose({q.x, q.y, q.yaw}, d);
    q.x = moved.x;
    q.y = moved.y;
    q.yaw = geom::wrap_angle(moved.yaw);
  }
  bias_moments();
}

void ParticleLocalizer::take_points(const LidarScan& scan) {
  points_.clear();
  if (valid_returns(scan) < motion_.min_informative_beams) return;
  points_ = scan_points(scan, std::max(1, p_.beams));
  hit_sigma_m_ = std::hypot(p_.field_sigma_m, range_sigma_m());
  // A set spread over metres (after a kidnap, a reseed) has particles centimetres apart at best:
  // weighed with the sharp likelihood, the one that happens to sit nearest a partial fit takes
  // all the weight within a few scans, wherever the truth is. Weighed with a wider one until it
  // has settled, it narrows as the evidence builds (AMCL's default sigma_hit is 0.2 m).
  weigh_sigma_m_ = health_ == LocalizationHealth::kOk
                       ? hit_sigma_m_
                       : std::hypot(hit_sigma_m_, p_.unsettled_sigma_m);
}

void ParticleLocalizer::tabulate_log_likelihood() {
  if (weigh_sigma_m_ == tabulated_sigma_m_) return;
  tabulated_sigma_m_ = weigh_sigma_m_;
  per_reach_squared_ = 1.0 / sq(field_->reach_m());
  // log(z_hit exp(-d^2 / 2 s^2) + z_rand) against d^2 up to the field's reach: a table of it,
  // interpolated, in place of an exp and a log per beam and particle (the filter's main cost).
  const double k = 0.5 / sq(weigh_sigma_m_);
  log_table_.resize(kLogTableSize + 1);
  for (std::size_t i = 0; i <= kLogTableSize; ++i)
    log_table_[i] = std::log(
        p_.z_hit * std::exp(-k * static_cast<double>(i) / kLogTableSize * sq(field_->reach_m())) +
        p_.z_rand);
}

double ParticleLocalizer::weigh() {
  if (points_.empty()) return -1;
  const double beams = static_cast<double>(points_.size());
  tabulate_log_likelihood();
  std::vector<double> log_w(set_.size());
  double best = -INFINITY;
  for (std::size_t n = 0; n < set_.size(); ++n) {
    const Particle& q = set_[n];
    const double c = std::cos(q.yaw), s = std::sin(q.yaw);
    double l = 0;
    for (const geom::Vec2& e : points_)
      l += log_likelihood(field_->distance({q.x + c * e.x - s * e.y, q.y + s * e.x + c * e.y}));
    log_w[n] = l;
    best = std::max(best, l);
  }
  // Augmented MCL's measure of fit: the prior-weighted mean of each particle's likelihood per
  // beam (a geometric mean, so that it does not depend on how many beams were weighed).
  double fit = 0, total = 0;
  for (std::size_t n = 0; n < set_.size(); ++n) {
    fit += set_[n].w * std::exp(log_w[n] / beams);
    set_[n].w *= std::exp(log_w[n] - best);
    total += set_[n].w;
  }
  for (Particle& q : set_)
    q.w = total > 0 && std::isfinite(total) ? q.w / total : 1.0 / set_.size();
  return fit;
}

void ParticleLocalizer::resample(const std::vector<Place>& candidates, double fresh) {
  const WeightedDraw draw(set_);
  std::unordered_set<std::uint64_t> bins;
  const std::size_t floor = static_cast<std::size_t>(std::max(1, p_.min_particles));
  const std::size_t ceiling = std::max(floor, static_cast<std::size_t>(p_.max_particles));
  // The kept share: KLD sampling's count for the bins that draws by the weights fill, then
  // that many drawn by low-variance (systematic) resampling, one random offset for all. Drawn
  // one by one, copies are a random walk in which a direction the scans leave open (along a
  // lone wall) loses its spread within a few dozen resamplings, and the set reports itself sure
  // of what nothing measured.
  const double kept_share = candidates.empty() ? 1.0 : 1.0 - fresh;
  std::size_t needed = floor, counted = 0;
  while (counted < ceiling) {
    bins.insert(key_of(bin_of(draw(set_, rng_), p_)));
    ++counted;
    needed = std::clamp(static_cast<std::size_t>(kld_count(bins.size(), p_.kld_error, p_.kld_z)),
                        floor, ceiling);
    if (static_cast<double>(counted) >= kept_share * static_cast<double>(needed)) break;
  }
  systematic_draw(counted);
  if (fresh >= 1.0) scratch_.clear();  // a handover: the estimate's place was ruled out
  // Sensor resetting: the fresh share about the places the scan fits, split evenly, each drawn
  // over its place's spread (Olson's covariance of the near-best poses): along a lone wall, where
  // the scan leaves the place open, the fresh particles cover the wall rather than points a
  // metre apart.
  const std::size_t kept = scratch_.size();
  std::vector<double> inverse_density;
  if (!candidates.empty()) {
    const std::size_t room = ceiling > scratch_.size() ? ceiling - scratch_.size() : 0;
    const std::size_t each = std::min(
        room / candidates.size(),
        std::max<std::size_t>(
            30, static_cast<std::size_t>(fresh * static_cast<double>(needed)) / candidates.size()));
    std::vector<PlaceSpread> places;
    for (const Place& place : candidates)
      places.emplace_back(
          place, Eigen::Vector3d(matcher_->resolution_m(), matcher_->resolution_m(), 0.03));
    for (const PlaceSpread& place : places)
      for (std::size_t k = 0; k < each; ++k) {
        const geom::Pose2 x = place.draw([&] { return normal(1.0); });
        scratch_.push_back({x.x, x.y, x.yaw, bias_ + normal(std::sqrt(bias_var_)), 1.0});
        // Importance weight: one over the density the fresh particles were drawn from (the
        // mixture of the places), so that a place drawn densely (a tight match) does not win
        // over one drawn thinly (a match open along a wall) by numbers alone.
        double density = 0;
        for (const PlaceSpread& other : places) density += other.density(x);
        inverse_density.push_back(1.0 / std::max(density, 1e-300));
      }
  }
  // Roughening: copies of one particle spread a little, so that repeated weighing at rest does
  // not collapse the set onto a point (it would be sure of itself beyond what the scans say).
  for (Particle& q : scratch_) {
    q.x += normal(p_.jitter_m);
    q.y += normal(p_.jitter_m);
    q.yaw = geom::wrap_angle(q.yaw + normal(p_.jitter_rad));
  }
  // The kept particles weigh alike; the fresh ones by their importance weights, scaled so that
  // the fresh share keeps its share of the weight.
  double mean_inverse = 0;
  for (double v : inverse_density) mean_inverse += v / static_cast<double>(inverse_density.size());
  const double n = static_cast<double>(scratch_.size());
  for (std::size_t k = 0; k < scratch_.size(); ++k)
    scratch_[k].w = (k < kept ? 1.0 : inverse_density[k - kept] / mean_inverse) / n;
  set_.swap(scratch_);
}

void ParticleLocalizer::systematic_draw(std::size_t count) {
  scratch_.clear();
  double total = 0;
  for (const Particle& q : set_) total += q.w;
  const double step = total / static_cast<double>(std::max<std::size_t>(1, count));
  double next = step * rng_.uniform(), cumulative = 0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < count; ++k, next += step) {
    while (n + 1 < set_.size() && cumulative + set_[n].w < next) cumulative += set_[n++].w;
    scratch_.push_back(set_[n]);
  }
}

void ParticleLocalizer::summarise() {
  // The heaviest bin, and the cluster of particles in it and its neighbours.
  std::unordered_map<std::uint64_t, double> weight;
  const Particle* heaviest = &set_.front();
  double heaviest_w = -1;
  for (const Particle& q : set_) {
    const double w = weight[key_of(bin_of(q, p_))] += q.w;
    if (w > heaviest_w) {
      heaviest_w = w;
      heaviest = &q;
    }
  }
  const Bin top = bin_of(*heaviest, p_);
  const std::int64_t turns = static_cast<std::int64_t>(std::ceil(2.0 * M_PI / p_.bin_yaw_rad));
  double w = 0, x = 0, y = 0, c = 0, s = 0;
  for (const Particle& q : set_) {
    const Bin b = bin_of(q, p_);
    const std::int64_t dt = ((b.t - top.t) % turns + turns) % turns;
    if (std::abs(b.x - top.x) > 1 || std::abs(b.y - top.y) > 1 || (dt > 1 && dt < turns - 1))
      continue;
    w += q.w;
    x += q.w * q.x;
    y += q.w * q.y;
    c += q.w * std::cos(q.yaw);
    s += q.w * std::sin(q.yaw);
  }
  estimate_ = {x / w, y / w, std::atan2(s, c)};
  // The whole set about it: other live hypotheses widen it.
  covariance_.setZero();
  for (const Particle& q : set_) {
    const Eigen::Vector3d d(q.x - estimate_.x, q.y - estimate_.y,
                            geom::wrap_angle(q.yaw - estimate_.yaw));
    covariance_ += q.w * d * d.transpose();
  }
  covariance_.diagonal().array() += 1e-8;
}

double ParticleLocalizer::explained_share(const geom::Pose2& pose) const {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  int explained = 0;
  for (const geom::Vec2& e : points_)
    explained +=
        std::fabs(field_->distance({pose.x + c * e.x - s * e.y, pose.y + s * e.x + c * e.y})) <=
        3.0 * hit_sigma_m_;
  return static_cast<double>(explained) / static_cast<double>(points_.size());
}

void ParticleLocalizer::judge(const LidarScan& scan) {
  residuals_.clear();
  const std::optional<double> agree =
      scan_agreement(raycaster_, scan, estimate_, global_.verify_tolerance_m, &residuals_);
  const double share = points_.empty() ? -1.0 : explained_share(estimate_);

  // The view changed at once: a scan the map explained about the estimate is followed by one
  // it does not. On open ground, with fewer returns than a contradiction needs, this is what a
  // kidnap looks like (a box the map lacks comes into view over many scans, not in one).
  const int returns = valid_returns(scan);
  const bool was_explained =
      last_share_ >= global_.verify_agreement && last_returns_ >= p_.view_change_returns;
  const bool now_unexplained = share >= 0 && share < p_.min_explained &&
                               static_cast<int>(points_.size()) >= p_.view_change_returns;
  // ... or the returns the map explained vanished at once (most of them: dropouts take a few).
  const bool vanished = returns < p_.min_explained * last_returns_;
  if (was_explained && (now_unexplained || vanished))
    view_changed_scans_ = 1;
  else if (view_changed_scans_ > 0 && (share < 0 || share < p_.min_explained))
    ++view_changed_scans_;
  else
    view_changed_scans_ = 0;
  last_share_ = share;
  last_returns_ = returns;
  const bool unexplained = share >= 0 && share < p_.min_explained &&
                           (returns >= p_.min_returns || view_changed_scans_ > 0);
  estimate_agrees_ = !agree || *agree >= global_.verify_agreement;  // none: nothing against it
  if (confirm_.active) confirm(scan, agree);
  if (!agree && !unexplained) {
    // Too few beams meet a mapped surface to judge by agreement; but a scan of min_returns whose
    // returns the map explains in fair share ends a run of contradictions (a box the map lacks
    // filling the view had left the count frozen, the filter degraded and the robot waiting for
    // it until it gave up: held-out yard_s7 seed 1 with three unmapped boxes).
    if (share >= p_.min_explained && returns >= p_.min_returns) failed_matches_ = 0;
    return;
  }
  failed_matches_ = unexplained || *agree < p_.contradicted_agreement ? failed_matches_ + 1 : 0;
  if (motion_.learn_noise && agree && *agree >= global_.verify_agreement &&
      static_cast<int>(residuals_.size()) >= motion_.min_informative_beams)
    range_learnt_.add(robust_variance(residuals_));
}

ParticleLocalizer::Place ParticleLocalizer::polish(const LidarScan& scan, Place place) const {
  // A wide window is searched in coarse rotation steps (a return 20 m away moves up to 17 cm
  // between them): each place it finds is matched again in a narrow window at full resolution,
  // climbing while that improves it, so that places are ranked by how well the scan fits them,
  // not by how near the coarse grid passed to each. The narrow match's spread says along what
  // the scan leaves the place open (a lone wall).
  const MatchWindow narrow{0.5 * global_.matcher.apart_m, 0.5 * global_.matcher.apart_rad};
  for (int climb = 0; climb < 4; ++climb) {
    const std::optional<ScanMatch> fine = matcher_->match(scan, place.pose, narrow);
    if (!fine || fine->score <= place.score) break;
    place = {fine->pose, fine->score, fine->spread};
  }
  return place;
}

ParticleLocalizer::Reseed ParticleLocalizer::reseed_candidates(const LidarScan& scan) {
  Reseed out;
  if (!matcher_) matcher_.emplace(map_, reseed_matcher(global_.matcher));
  const MatchWindow window{p_.reseed_tile_m, M_PI};
  auto apart = [&](const geom::Pose2& l, const geom::Pose2& r) {
    return geom::distance(l.position(), r.position()) > global_.matcher.apart_m ||
           std::fabs(geom::wrap_angle(l.yaw - r.yaw)) > global_.matcher.apart_rad;
  };
  auto by_score = [](const Place& l, const Place& r) { return l.score > r.score; };
  std::vector<Place> found;
  const int rings = std::max(0, p_.reseed_rings - 1);
  for (int ring = 0; ring <= rings; ++ring) {
    for (int a = -ring; a <= ring; ++a)
      for (int b = -ring; b <= ring; ++b) {
        if (std::max(std::abs(a), std::abs(b)) != ring) continue;
        const geom::Pose2 centre{estimate_.x + 2.0 * p_.reseed_tile_m * a,
                                 estimate_.y + 2.0 * p_.reseed_tile_m * b, estimate_.yaw};
        const std::optional<ScanMatch> m = matcher_->match(scan, centre, window);
        if (!m) continue;
        for (const auto& [pose, score] : m->alternatives) {
          const Place place = polish(scan, {pose, score, m->spread});
          if (place.score >= global_.matcher.min_score) found.push_back(place);
        }
      }
    // The best place for the scan about the estimate is the estimate itself: what the map did not
    // explain are things it lacks (boxes, people), not a kidnap. Nothing wider is searched.
    if (ring == 0 && !doubted_ && estimate_agrees_ && !found.empty() &&
        !apart(std::min_element(found.begin(), found.end(), by_score)->pose, estimate_)) {
      out.estimate_fits = true;
      return out;
    }
  }
  // No place fits the scan well anywhere: what it sees is mostly things the map lacks (a box in
  // an open yard). No evidence against the estimate either.
  out.estimate_fits = found.empty();
  std::stable_sort(found.begin(), found.end(), by_score);
  const std::vector<geom::Vec2> points = scan_points(scan, 90);
  for (Place f : found) {
    if (static_cast<int>(out.candidates.size()) >= p_.max_places) break;
    if (!std::all_of(out.candidates.begin(), out.candidates.end(),
                     [&](const Place& k) { return apart(k.pose, f.pose); }))
      continue;
    f.pose = refine_on_field(*field_, points, f.pose, 0.2, 0.05);
    const std::optional<double> agree =
        scan_agreement(raycaster_, scan, f.pose, global_.verify_tolerance_m);
    if (agree && *agree >= global_.verify_agreement) out.candidates.push_back(f);
  }
  // The best confirmed place is the estimate itself (a scan that agreed less than it should:
  // noise, things the map lacks): nothing to reseed, unless a failed confirmation doubts it.
  if (!doubted_ && !out.candidates.empty() && !apart(out.candidates.front().pose, estimate_)) {
    out.candidates.clear();
    out.estimate_fits = true;
  }
  return out;
}

void ParticleLocalizer::observe(const LidarScan& scan) {
  // Settled and barely moved: the scan is judged at the dead-reckoned estimate, the particles
  // left alone (weighing the same view again would make the set surer than the scans are).
  const bool deferred = may_defer();
  if (deferred)
    defer_motion();
  else
    apply_motion();
  take_points(scan);
  if (!deferred) {
    const double fit = weigh();
    if (fit >= 0) {
      since_weigh_m_ = since_weigh_rad_ = 0;
      if (w_slow_ <= 0) w_slow_ = w_fast_ = fit;
      w_slow_ += p_.alpha_slow * (fit - w_slow_);
      w_fast_ += p_.alpha_fast * (fit - w_fast_);
    }
    summarise();
  }
  judge(scan);
  // Sensor resetting where the map contradicts the estimate (or it is lost).
  std::vector<Place> candidates;
  // Contradicted, not merely wide: a set spread over open ground contracts by itself when the
  // plant comes into view, and look-alikes drawn in would only split it.
  const bool contradicted = failed_matches_ >= 2;
  const bool handover = !handover_.empty();
  if (handover) {
    candidates.swap(handover_);
    handover_.clear();
    unmatched_ = false;
  } else if (!contradicted) {
    unmatched_ = false;
  } else if (scan.t_s + 1e-9 >= next_reseed_s_ && valid_returns(scan) >= p_.min_returns) {
    Reseed found = reseed_candidates(scan);  // (estimate_fits: nothing against it)
    doubted_ = false;
    candidates = std::move(found.candidates);
    if (found.estimate_fits) failed_matches_ = 0;
    unmatched_ = candidates.empty() && !found.estimate_fits;
    // A search that finds nothing is repeated less and less often (up to 8 periods apart): it
    // costs, and while the view does not change it will find nothing again.
    reseed_backoff_ = unmatched_ ? std::min(8, 2 * reseed_backoff_) : 1;
    next_reseed_s_ = scan.t_s + reseed_backoff_ * global_.global_match_period_s;
  }
  if (deferred && candidates.empty() && !nudge_) {  // the weights did not change
    update_health();
    return;
  }
  apply_motion();  // (held back on this scan: the redraw needs the particles where they are)
  double squares = 0;
  for (const Particle& q : set_) squares += q.w * q.w;
  const double effective = 1.0 / squares;
  if (!candidates.empty()) {
    const double demand = w_slow_ > 0 ? 1.0 - w_fast_ / w_slow_ : 0.0;
    resample(candidates,
             handover ? 1.0 : std::clamp(std::max(demand, p_.reseed_fraction), 0.0, 0.9));
    ++relocalizations_;
    confirm_ = {true, 0, 0, 0, 0};
    view_changed_scans_ = 0;
    std::vector<geom::Pose2> places;
    for (const Place& c : candidates) places.push_back(c.pose);
    places_.reset(places);
    summarise();
  } else if (nudge_) {
    resample({*nudge_}, p_.reseed_fraction);
    nudge_.reset();
    summarise();
  } else if (effective < 0.5 * static_cast<double>(set_.size())) {
    resample({}, 0.0);
    summarise();
  }
  update_health();
}

void ParticleLocalizer::widen(double position_sigma_m, double yaw_sigma_rad) {
  apply_motion();
  // Widened to at least the asked spread, not by it again and again: a set already that wide
  // holds the hypotheses it needs (repeated additions while the robot waits scattered it over
  // metres of look-alikes).
  position_sigma_m =
      std::sqrt(std::max(0.0, sq(position_sigma_m) - sq(ParticleLocalizer::position_sigma_m())));
  yaw_sigma_rad =
      std::sqrt(std::max(0.0, sq(yaw_sigma_rad) - sq(ParticleLocalizer::yaw_sigma_rad())));
  if (position_sigma_m <= 0 && yaw_sigma_rad <= 0) return;
  // Enough particles to cover the wider spread, drawn by the weights first.
  const std::size_t n = std::min<std::size_t>(
      static_cast<std::size_t>(std::max(1, p_.max_particles)),
      std::max<std::size_t>(set_.size(), static_cast<std::size_t>(4 * p_.min_particles)));
  const WeightedDraw draw(set_);
  scratch_.clear();
  for (std::size_t k = 0; k < n; ++k) {
    Particle q = draw(set_, rng_);
    q.x += normal(position_sigma_m);
    q.y += normal(position_sigma_m);
    q.yaw = geom::wrap_angle(q.yaw + normal(yaw_sigma_rad));
    q.w = 1.0 / static_cast<double>(n);
    scratch_.push_back(q);
  }
  set_.swap(scratch_);
  summarise();
  update_health();
}

geom::Pose2 ParticleLocalizer::pose() const {
  const geom::Pose2 p = geom::compose(estimate_, pending_.delta);
  return {p.x, p.y, geom::wrap_angle(p.yaw)};
}

Eigen::Matrix3d ParticleLocalizer::pose_covariance() const {
  Eigen::Matrix3d c = covariance_;
  const Pending m = chain(deferred_, pending_);
  const double along = sq(motion_.distance_noise * m.moved_m);
  c(0, 0) += along;
  c(1, 1) += along;
  c(2, 2) += m.gyro_var + bias_var_ * sq(m.time_s);  // the biases' spread
  return c;
}

double ParticleLocalizer::position_sigma_m() const {
  const Eigen::Matrix3d c = pose_covariance();
  const double mean = 0.5 * (c(0, 0) + c(1, 1));
  const double half = 0.5 * (c(0, 0) - c(1, 1));
  return std::sqrt(std::max(0.0, mean + std::sqrt(half * half + c(0, 1) * c(0, 1))));
}

double ParticleLocalizer::yaw_sigma_rad() const {
  return std::sqrt(std::max(0.0, pose_covariance()(2, 2)));
}

PlaceHypotheses::Verdict ParticleLocalizer::judge_place(const LidarScan& scan, geom::Pose2& place) {
  if (points_.empty()) return {};
  // Refined within a few centimetres only: the odometry drifts that little between scans, and a
  // wider reach would let a look-alike slide along a corridor to keep fitting.
  place = refine_on_field(*field_, points_, place, 0.05, 0.01);
  const std::optional<double> agree =
      scan_agreement(raycaster_, scan, place, global_.verify_tolerance_m);
  const bool contradicted =
      (agree && *agree < p_.contradicted_agreement) ||
      (valid_returns(scan) >= p_.min_returns && explained_share(place) < p_.min_explained);
  return {contradicted, points_log_likelihood(place)};
}

double ParticleLocalizer::points_log_likelihood(const geom::Pose2& pose) {
  tabulate_log_likelihood();
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  double l = 0;
  for (const geom::Vec2& e : points_)
    l += log_likelihood(field_->distance({pose.x + c * e.x - s * e.y, pose.y + s * e.x + c * e.y}));
  return l;
}

void ParticleLocalizer::confirm(const LidarScan& scan, const std::optional<double>& agree) {
  places_.check([&](geom::Pose2& place) { return judge_place(scan, place); }, p_.confirm_strikes,
                p_.rival_margin);
  const std::vector<geom::Pose2> rivals =
      places_.rivals(estimate_, global_.matcher.apart_m, global_.matcher.apart_rad);
  // Progress counts only while the set is one hypothesis: two live ones are not yet a place.
  if (position_sigma_m() > motion_.lost_position_sigma_m) {
    confirm_.turned_rad = confirm_.moved_m = 0;
    return;
  }
  // The estimate's own place ruled out while others live: the set chose a look-alike.
  if (!rivals.empty() &&
      !places_.holds(estimate_, global_.matcher.apart_m, global_.matcher.apart_rad)) {
    confirm_.turned_rad = confirm_.moved_m = 0;
    confirm_.strikes = 0;
    for (const geom::Pose2& r : rivals) handover_.push_back({r, 0, Eigen::Matrix3d::Zero()});
    return;
  }
  // The estimate's own place, refined scan by scan, has moved off it: the set lost the spread
  // that held the truth (along a wall the scans leave open, until a corner comes into view).
  // Fresh particles are drawn about the place and the scans choose.
  const std::optional<geom::Pose2> own =
      places_.nearest(estimate_, global_.matcher.apart_m, global_.matcher.apart_rad);
  const bool own_off =
      own && geom::distance(own->position(), estimate_.position()) > p_.place_offset_m;
  // ... unless the estimate fits the scan clearly better than its place does (by kClearlyBetter
  // nats: along a lone wall both fit alike, and there the place is the guard): then the place is
  // what drifted (refined a few centimetres a scan, it cannot climb out once the wall's end comes
  // into view), and it moves onto the estimate. Drawing particles about it would pull the set off
  // the better fit, scan after scan (training yard_s2, seed 4: the place 0.42 m off and 19 nats
  // worse, the estimate 1 cm off, the confirmation started again every third scan until the
  // robot gave up).
  constexpr double kClearlyBetter = 5.0;
  if (own_off && points_log_likelihood(estimate_) >= points_log_likelihood(*own) + kClearlyBetter) {
    places_.move_nearest(estimate_, global_.matcher.apart_m, global_.matcher.apart_rad, estimate_);
    confirm_.offset_scans = 0;
  } else if (own_off) {
    if (++confirm_.offset_scans >= p_.confirm_strikes) {
      confirm_.turned_rad = confirm_.moved_m = 0;
      confirm_.offset_scans = 0;
      nudge_ = Place{*own, 0, Eigen::Matrix3d::Zero()};
    }
    return;
  }
  confirm_.offset_scans = 0;
  if (agree && *agree < p_.contradicted_agreement) {
    confirm_.turned_rad = confirm_.moved_m = 0;
    if (++confirm_.strikes >= p_.confirm_strikes) {
      confirm_.strikes = 0;
      if (!rivals.empty()) {
        for (const geom::Pose2& r : rivals) handover_.push_back({r, 0, Eigen::Matrix3d::Zero()});
      } else {
        doubted_ = true;
        failed_matches_ = std::max(failed_matches_, 2);  // reseed
      }
    }
    return;
  }
  // A rival place still agreeing with every view so far: the estimate is one of two look-alikes.
  if (!rivals.empty()) return;
  if (confirm_.turned_rad >= p_.confirm_turn_rad || confirm_.moved_m >= p_.confirm_move_m) {
    confirm_ = {};
    places_.clear();
  }
}

void ParticleLocalizer::update_health() {
  const double sigma = position_sigma_m();
  if (confirm_.active || sigma > motion_.lost_position_sigma_m ||
      failed_matches_ >= motion_.lost_failed_matches ||
      view_changed_scans_ >= p_.view_change_lost_scans)
    health_ = LocalizationHealth::kLost;
  else if (sigma > motion_.ok_position_sigma_m || failed_matches_ >= 5)
    health_ = LocalizationHealth::kDegraded;
  else
    health_ = LocalizationHealth::kOk;
}

}  // namespace plantsim::robot
