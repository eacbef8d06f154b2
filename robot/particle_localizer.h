// Localisation by particles (`localization.estimator: particles`), as AMCL does it (Thrun,
// Burgard and Fox, Probabilistic Robotics, ch. 8; Nav2's nav2_amcl): poses drawn by the
// odometry's motion model, weighed by a likelihood field (each return scored by its distance to
// the nearest mapped surface: likelihood_field.h), resampled when the weights
// degenerate, in numbers chosen by KLD sampling (Fox 2003). Found again after a kidnap by
// sensor resetting (Lenser and Veloso 2000): where the scans contradict the estimate beam by beam,
// particles are drawn about the places a global scan match finds for the scan, in a square of
// tiles about the estimate, as many as augmented MCL's w_fast/w_slow asks (at least
// `reseed_fraction`). The estimate is the best cluster's mean; its covariance is the whole set's
// about it, so that two live hypotheses make it wide (and the robot not localised) until the
// scans decide. Where it departs from AMCL: no uniform random particles (on a 100 m plant they
// would never land near the truth), and reseeding only where the map contradicts the estimate
// (a box the map lacks lowers AMCL's average weight as a kidnap does). After a reseed, its
// places are kept and judged scan by scan (place_hypotheses.h): the estimate is confirmed only
// once no rival lives and it has turned and moved; when its own place drifts off it, fresh
// particles are drawn about the place. A view that changes at once (a kidnap on open ground)
// makes the filter lost within half a second. As AMCL, the set starts at `max_particles` drawn
// from the prior (KLD sampling then chooses fewer), and a settled filter weighs a scan only after
// `update_min_m` of travel or `update_min_rad` of turn: in between the particles are left alone,
// the estimate follows the odometry and every scan is still judged against the map.
//
// The parts, each in its own file and owning its parameters and state, as nav2_amcl splits
// them: the motion model (particle_motion_model.h), the likelihood field model
// (particle_field_model.h), KLD sampling (particle_kld_sampler.h), recovery with w_slow / w_fast
// (particle_recovery.h) about the places a global match finds (particle_place_search.h), the
// clusters (particle_clusters.h) and the confirmation of a reseeded estimate
// (particle_confirmation.h). This class owns the cycle, the judging of each scan and the health.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "robot/ekf_localizer.h"
#include "robot/global_match.h"
#include "robot/noise_learning.h"
#include "robot/particle_clusters.h"
#include "robot/particle_confirmation.h"
#include "robot/particle_field_model.h"
#include "robot/particle_kld_sampler.h"
#include "robot/particle_motion_model.h"
#include "robot/particle_place_search.h"
#include "robot/particle_recovery.h"
#include "robot/particle_set.h"
#include "robot/place_hypotheses.h"
#include "robot/pose_estimator.h"
#include "util/random_stream.h"

namespace plantsim::robot {

/// The particle filter's parameters (section `particles`): its parts' own, then the cycle's.
struct ParticleParams {
  KldSamplerParams kld;                ///< the set's size, bins and roughening
  ParticleFieldParams field;           ///< the likelihood field model
  ParticleMotionParams motion;         ///< the motion model (`motion_*` keys)
  ParticleRecoveryParams recovery;     ///< w_slow / w_fast and the share drawn anew
  ParticlePlaceSearchParams search;    ///< where fresh particles are drawn
  ParticleConfirmationParams confirm;  ///< a reseeded estimate's confirmation
  /// A settled filter weighs a scan after this much travel or turn (AMCL's defaults): the same
  /// view weighed again makes the set surer than the scans are, and costs (at 0.05 m and rad a
  /// particle filter episode cost 2.6 to 5.2 times the EKF's).
  double update_min_m = 0.25;
  double update_min_rad = 0.2;
  /// A scan agreeing with the map (global_match.h's beam-by-beam agreement) less than this at
  /// the estimate contradicts it (a failed match).
  double contradicted_agreement = 0.7;
  /// ... or fewer than this share of the weighed returns lies within three sigmas of a mapped
  /// surface at the estimate (on open ground after a kidnap few beams can contradict it, yet
  /// what the scan sees is nowhere on the map there).
  double min_explained = 0.3;
  int min_returns = 20;  ///< returns a scan needs to contradict the estimate or to be matched
  /// ... except after the view changed at once (a scan explained, at least verify_agreement of
  /// its returns near mapped surfaces, followed by one explained less than min_explained, each
  /// with this many returns, or by one whose returns fell below min_explained of the last's): a
  /// kidnap on open ground, where a handful of returns is all there is. Unexplained scans then
  /// contradict the estimate from this many returns, and after `view_change_lost_scans` of them in
  /// a row the filter reports itself lost.
  int view_change_returns = 10;
  int view_change_lost_scans = 8;
  int seed = 1;  ///< the filter's random numbers (deterministic per seed)
};

class ParticleLocalizer final : public PoseEstimator {
 public:
  /// `told` gives what the robot is told and shares with the EKF: its start's uncertainty, the
  /// gyro's and the lidar's noise (and how they are learnt) and the health thresholds. The
  /// motion's noise is the filter's own (params.motion).
  ParticleLocalizer(const worlds::World& map, const MapRaycaster& raycaster, const EkfParams& told,
                    const GlobalMatchParams& global, const ParticleParams& params);

  void predict(double distance_m, double gyro_yaw_rate_radps, double dt_s) override;
  void standstill(double gyro_yaw_rate_radps, double dt_s) override;
  void observe(const LidarScan& scan) override;
  void widen(double position_sigma_m, double yaw_sigma_rad) override;
  geom::Pose2 pose() const override;
  Eigen::Matrix3d pose_covariance() const override;
  double position_sigma_m() const override;
  double yaw_sigma_rad() const override;
  double gyro_bias_radps() const override { return bias_; }
  double range_sigma_m() const override {
    return told_.learn_noise ? range_learnt_.sigma(told_.range_sigma_m) : told_.range_sigma_m;
  }
  LocalizationHealth health() const override { return health_; }
  int failed_matches() const override { return failed_matches_; }
  bool lost_in_view() const override { return health_ == LocalizationHealth::kLost && unmatched_; }
  int relocalizations() const override { return relocalizations_; }

  using Place = ParticlePlace;
  using Particle = robot::Particle;
  /// The set after the last update (pending and deferred motion not applied), weights summing
  /// to one.
  const std::vector<Particle>& particles() const { return set_; }

 private:
  /// The motion since the last scan, and any deferred before it, applied to the particles.
  void apply_motion();
  /// A settled filter between updates, as AMCL: the motion since the last scan is held back from
  /// the particles (applied with the next update, in one draw) and the estimate dead-reckoned.
  void defer_motion();
  /// Whether this scan may leave the particles alone: the filter is settled, no confirmation or
  /// redraw is pending and it has moved less than update_min_m and turned less than
  /// update_min_rad since it last weighed.
  bool may_defer() const;
  /// KLD resampling into n drawn by the weights, plus `fresh` about the candidate places (1: the
  /// set replaced by particles about them).
  void resample(const std::vector<Place>& candidates, double fresh);
  /// The estimate and covariance from the set (particle_clusters.h).
  void summarise();
  void judge(const LidarScan& scan);
  void update_health();
  /// One reading at rest: the Kalman update of the set's bias.
  void update_bias(double gyro_yaw_rate_radps);
  /// bias_ and bias_var_ from the set.
  void bias_moments();
  /// The gyro's noise the filter uses (told or learnt).
  double gyro_sigma_radps() const;
  double normal(double sigma) { return particle_normal(rng_, sigma); }

  const MapRaycaster& raycaster_;
  EkfParams told_;
  GlobalMatchParams global_;
  ParticleParams p_;
  // The parts, as AMCL splits them.
  ParticleMotionModel motion_;
  ParticleFieldModel field_;
  KldSampler sampler_;
  ParticleRecovery recovery_;
  ParticlePlaceSearch search_;
  ParticleConfirmation confirmation_;
  util::RandomStream rng_;
  std::vector<Particle> set_, scratch_;
  double since_weigh_m_ = 0, since_weigh_rad_ = 0;
  geom::Pose2 estimate_;  // best cluster's mean, at the last scan
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Zero();
  double bias_ = 0, bias_var_ = 0;  // the set's mean bias and its variance
  LearntVariance range_learnt_;
  GyroRestNoise gyro_learnt_;
  std::vector<double> residuals_;
  int failed_matches_ = 0;
  LocalizationHealth health_ = LocalizationHealth::kOk;
  bool unmatched_ = false;
  int relocalizations_ = 0;
  double last_share_ = -1;        // the last scan's explained share at the estimate
  int last_returns_ = 0;          // and its valid returns
  int view_changed_scans_ = 0;    // unexplained scans since the view changed at once
  bool estimate_agrees_ = false;  // the last scan agreed with the map at the estimate
};

}  // namespace plantsim::robot
