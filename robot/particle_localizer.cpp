// The particle filter's cycle (its parts: particle_localizer.h): motion applied or held back,
// the set weighed, resampled or reseeded, the estimate judged against the map scan by scan, a
// reseeded estimate confirmed, and the health.
#include "robot/particle_localizer.h"

#include <algorithm>
#include <cmath>

#include "robot/median_spread.h"

namespace plantsim::robot {
namespace {

double squared(double v) { return v * v; }

// Robust variance of residuals: the median absolute deviation's, scaled for a normal.
double robust_variance(std::vector<double>& r) { return squared(1.4826 * median_spread(r).mad); }

}  // namespace

ParticleLocalizer::ParticleLocalizer(const worlds::World& map, const MapRaycaster& raycaster,
                                     const EkfParams& told, const GlobalMatchParams& global,
                                     const ParticleParams& params)
    : raycaster_(raycaster),
      told_(told),
      global_(global),
      p_(params),
      motion_(params.motion),
      field_(map, params.field),
      sampler_(params.kld),
      recovery_(params.recovery),
      search_(map, raycaster, global, params.search),
      confirmation_(params.confirm,
                    {params.contradicted_agreement, params.min_explained, params.min_returns},
                    global),
      rng_(static_cast<std::uint64_t>(params.seed) ^ 0x7061727469636c65ULL),  // "particle"
      range_learnt_(told.range_learning_rate),
      gyro_learnt_(told.gyro_learning_rate, told.gyro_min_samples) {
  // As AMCL starts: the prior drawn at the ceiling, KLD sampling choosing fewer at the first
  // resampling. (Started at the floor, 200 draws of a three-dimensional prior left the truth
  // 2.5 sigmas out with no particle near it, and the first sharp weighing collapsed the set 12 cm
  // off with a spread of 5 mm.)
  const int n = std::max({1, p_.kld.min_particles, p_.kld.max_particles});
  set_.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    set_.push_back({map.start.x + normal(told.initial_position_sigma_m),
                    map.start.y + normal(told.initial_position_sigma_m),
                    geom::wrap_angle(map.start.yaw + normal(told.initial_yaw_sigma_rad)),
                    normal(told.initial_bias_sigma_radps), 1.0 / n});
  bias_moments();
  summarise();
  update_health();
}

double ParticleLocalizer::gyro_sigma_radps() const {
  return told_.learn_noise ? gyro_learnt_.sigma(told_.gyro_noise_radps) : told_.gyro_noise_radps;
}

void ParticleLocalizer::predict(double distance_m, double gyro_yaw_rate_radps, double dt_s) {
  if (dt_s <= 0) return;
  gyro_learnt_.reading();
  motion_.add(distance_m, (gyro_yaw_rate_radps - bias_) * dt_s, gyro_sigma_radps(), dt_s);
  update_health();
}

void ParticleLocalizer::standstill(double gyro_yaw_rate_radps, double dt_s) {
  if (dt_s <= 0) return;
  const double sigma = gyro_sigma_radps();
  if (!at_rest(gyro_yaw_rate_radps - bias_, sigma * sigma + bias_var_))
    return predict(0.0, gyro_yaw_rate_radps, dt_s);
  gyro_learnt_.reading();
  apply_motion();  // the motion so far under the biases as they were
  if (!told_.learn_noise) {
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
  const double r = squared(gyro_sigma_radps());
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
  for (const Particle& q : set_) var += q.w * squared(q.bias - mean);
  bias_ = mean;
  bias_var_ = var;
}

bool ParticleLocalizer::may_defer() const {
  return health_ == LocalizationHealth::kOk && failed_matches_ == 0 && !confirmation_.active() &&
         !confirmation_.nudge() && !confirmation_.handing_over() &&
         since_weigh_m_ + motion_.deferred().moved_m + motion_.pending().moved_m <
             p_.update_min_m &&
         since_weigh_rad_ + motion_.deferred().turned_rad + motion_.pending().turned_rad <
             p_.update_min_rad;
}

void ParticleLocalizer::defer_motion() {
  const geom::Pose2 moved = geom::compose(estimate_, motion_.defer());
  estimate_ = {moved.x, moved.y, geom::wrap_angle(moved.yaw)};
}

void ParticleLocalizer::apply_motion() {
  const OdometryDelta m = motion_.take();
  if (m.time_s <= 0) return;
  since_weigh_m_ += m.moved_m;
  since_weigh_rad_ += m.turned_rad;
  confirmation_.moved(m);
  motion_.sample(m, bias_, set_, rng_);
  bias_moments();
}

void ParticleLocalizer::resample(const std::vector<Place>& candidates, double fresh) {
  // The kept share: KLD sampling's count for the bins that draws by the weights fill, then
  // that many drawn by low-variance (systematic) resampling, one random offset for all.
  const double kept_share = candidates.empty() ? 1.0 : 1.0 - fresh;
  const KldSampler::Count count = sampler_.count(set_, kept_share, rng_);
  KldSampler::systematic_draw(set_, count.counted, rng_, scratch_);
  if (fresh >= 1.0) scratch_.clear();  // a handover: the estimate's place was ruled out
  // Sensor resetting: the fresh share about the places the scan fits, split evenly.
  const std::size_t kept = scratch_.size();
  std::vector<double> inverse_density;
  if (!candidates.empty()) {
    const double cell = search_.resolution_m();
    inverse_density = ParticleRecovery::inject(candidates, fresh, count.needed, sampler_.ceiling(),
                                               Eigen::Vector3d(cell, cell, 0.03), bias_, bias_var_,
                                               rng_, scratch_);
  }
  sampler_.roughen(scratch_, rng_);
  ParticleRecovery::weigh_resampled(scratch_, kept, inverse_density);
  set_.swap(scratch_);
}

void ParticleLocalizer::summarise() {
  const ParticleEstimate e =
      cluster_estimate(set_, sampler_.params().bin_xy_m, sampler_.params().bin_yaw_rad);
  estimate_ = e.pose;
  covariance_ = e.covariance;
}

void ParticleLocalizer::judge(const LidarScan& scan) {
  residuals_.clear();
  const std::optional<double> agree =
      scan_agreement(raycaster_, scan, estimate_, global_.verify_tolerance_m, &residuals_);
  const double share = field_.points().empty() ? -1.0 : field_.explained_share(estimate_);

  // The view changed at once: a scan the map explained about the estimate is followed by one
  // it does not. On open ground, with fewer returns than a contradiction needs, this is what a
  // kidnap looks like (a box the map lacks comes into view over many scans, not in one).
  const int returns = valid_returns(scan);
  const bool was_explained =
      last_share_ >= global_.verify_agreement && last_returns_ >= p_.view_change_returns;
  const bool now_unexplained = share >= 0 && share < p_.min_explained &&
                               static_cast<int>(field_.points().size()) >= p_.view_change_returns;
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
  if (confirmation_.active() &&
      confirmation_.check(scan, agree, estimate_, position_sigma_m(), told_.lost_position_sigma_m,
                          field_, raycaster_))
    failed_matches_ = std::max(failed_matches_, 2);  // reseed
  if (!agree && !unexplained) {
    // Too few beams meet a mapped surface to judge by agreement; but a scan of min_returns whose
    // returns the map explains in fair share ends a run of contradictions (a box the map lacks
    // filling the view had left the count frozen, the filter degraded and the robot waiting for
    // it until it gave up: held-out yard_s7 seed 1 with three unmapped boxes).
    if (share >= p_.min_explained && returns >= p_.min_returns) failed_matches_ = 0;
    return;
  }
  failed_matches_ = unexplained || *agree < p_.contradicted_agreement ? failed_matches_ + 1 : 0;
  if (told_.learn_noise && agree && *agree >= global_.verify_agreement &&
      static_cast<int>(residuals_.size()) >= told_.min_informative_beams)
    range_learnt_.add(robust_variance(residuals_));
}

void ParticleLocalizer::observe(const LidarScan& scan) {
  // Settled and barely moved: the scan is judged at the dead-reckoned estimate, the particles
  // left alone (weighing the same view again would make the set surer than the scans are).
  const bool deferred = may_defer();
  if (deferred)
    defer_motion();
  else
    apply_motion();
  field_.take(scan, told_.min_informative_beams, range_sigma_m(),
              health_ == LocalizationHealth::kOk);
  if (!deferred) {
    const double fit = field_.weigh(set_);
    if (fit >= 0) {
      since_weigh_m_ = since_weigh_rad_ = 0;
      recovery_.add_fit(fit);
    }
    summarise();
  }
  judge(scan);
  // Sensor resetting where the map contradicts the estimate (or it is lost).
  std::vector<Place> candidates;
  // Contradicted, not merely wide: a set spread over open ground contracts by itself when the
  // plant comes into view, and look-alikes drawn in would only split it.
  const bool contradicted = failed_matches_ >= 2;
  const bool handover = confirmation_.handing_over();
  if (handover) {
    candidates = confirmation_.take_handover();
    unmatched_ = false;
  } else if (!contradicted) {
    unmatched_ = false;
  } else if (search_.due(scan.t_s) && valid_returns(scan) >= p_.min_returns) {
    ParticlePlaceSearch::Result found =  // (estimate_fits: nothing against it)
        search_.search(scan, estimate_, !confirmation_.doubted(), estimate_agrees_, field_.field());
    confirmation_.clear_doubt();
    candidates = std::move(found.candidates);
    if (found.estimate_fits) failed_matches_ = 0;
    unmatched_ = candidates.empty() && !found.estimate_fits;
    // A search that finds nothing is repeated less and less often (up to 8 periods apart).
    search_.searched(scan.t_s, unmatched_);
  }
  if (deferred && candidates.empty() && !confirmation_.nudge()) {  // the weights did not change
    update_health();
    return;
  }
  apply_motion();  // (held back on this scan: the redraw needs the particles where they are)
  double squares = 0;
  for (const Particle& q : set_) squares += q.w * q.w;
  const double effective = 1.0 / squares;
  if (!candidates.empty()) {
    resample(candidates, handover ? 1.0 : recovery_.fresh_share());
    ++relocalizations_;
    confirmation_.start(candidates);
    view_changed_scans_ = 0;
    summarise();
  } else if (confirmation_.nudge()) {
    resample({*confirmation_.nudge()}, recovery_.params().reseed_fraction);
    confirmation_.clear_nudge();
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
  position_sigma_m = std::sqrt(
      std::max(0.0, squared(position_sigma_m) - squared(ParticleLocalizer::position_sigma_m())));
  yaw_sigma_rad = std::sqrt(
      std::max(0.0, squared(yaw_sigma_rad) - squared(ParticleLocalizer::yaw_sigma_rad())));
  if (position_sigma_m <= 0 && yaw_sigma_rad <= 0) return;
  // Enough particles to cover the wider spread, drawn by the weights first.
  const std::size_t n = std::min<std::size_t>(
      static_cast<std::size_t>(std::max(1, p_.kld.max_particles)),
      std::max<std::size_t>(set_.size(), static_cast<std::size_t>(4 * p_.kld.min_particles)));
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
  const geom::Pose2 p = geom::compose(estimate_, motion_.pending().delta);
  return {p.x, p.y, geom::wrap_angle(p.yaw)};
}

Eigen::Matrix3d ParticleLocalizer::pose_covariance() const {
  return motion_.grow(covariance_, bias_var_);
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

void ParticleLocalizer::update_health() {
  const double sigma = position_sigma_m();
  if (confirmation_.active() || sigma > told_.lost_position_sigma_m ||
      failed_matches_ >= told_.lost_failed_matches ||
      view_changed_scans_ >= p_.view_change_lost_scans)
    health_ = LocalizationHealth::kLost;
  else if (sigma > told_.ok_position_sigma_m || failed_matches_ >= 5)
    health_ = LocalizationHealth::kDegraded;
  else
    health_ = LocalizationHealth::kOk;
}

}  // namespace plantsim::robot
