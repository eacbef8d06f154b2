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
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "robot/ekf_localizer.h"
#include "robot/global_match.h"
#include "robot/likelihood_field.h"
#include "robot/noise_learning.h"
#include "robot/place_hypotheses.h"
#include "robot/pose_estimator.h"
#include "robot/scan_matcher.h"
#include "util/random_stream.h"

namespace plantsim::robot {

struct ParticleParams {
  int min_particles = 200;   ///< KLD sampling's floor (AMCL: 500)
  int max_particles = 2000;  ///< and its ceiling (AMCL: 2000)
  double kld_error = 0.05;   ///< bound on the K-L distance to the true posterior (AMCL: 0.01)
  double kld_z = 2.33;       ///< its upper quantile (0.99)
  double bin_xy_m = 0.5;     ///< histogram bins for KLD sampling and the clusters
  double bin_yaw_rad = 0.175;
  int beams = 40;  ///< beams per scan in the weights, spread evenly over the valid ones
  /// A return d from the nearest mapped surface scores z_hit exp(-d^2 / 2 s^2) + z_rand (z_rand:
  /// what the map does not explain, a box, a person), with s^2 the range noise the filter uses
  /// (told or learnt) plus field_sigma_m^2 (the map's error and the set's own spread).
  double z_hit = 0.9;
  double z_rand = 0.05;
  double field_sigma_m = 0.05;
  /// While the filter is not `ok` the weights use a likelihood this much wider (added in
  /// quadrature), so that a set spread over metres narrows as evidence builds, not at once.
  double unsettled_sigma_m = 0.2;
  double field_resolution_m = 0.05;  ///< the likelihood field's cells (likelihood_field.h)
  /// A settled filter weighs a scan after this much travel or turn (AMCL's defaults): the same
  /// view weighed again makes the set surer than the scans are, and costs (at 0.05 m and rad a
  /// particle filter episode cost 2.6 to 5.2 times the EKF's).
  double update_min_m = 0.25;
  double update_min_rad = 0.2;
  double alpha_slow = 0.001;  ///< augmented MCL's long- and short-term averages of the weight
  double alpha_fast = 0.1;
  double jitter_m = 0.003;    ///< roughening: each resampled copy spread by this (keeps the set
  double jitter_rad = 0.003;  ///< diverse; resampling happens only after weighing)
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
  double reseed_fraction = 0.5;  ///< at least this share is drawn anew when the map contradicts
  double reseed_tile_m = 3.5;    ///< half-size of one global match's window (all headings)
  int reseed_rings = 2;  ///< tiles searched: this many rings of them about the estimate (2: the
                         ///< square 10.5 m about it, with tiles of 3.5 m)
  /// After a reseed the filter reports itself lost until its estimate is confirmed by views the
  /// reseed did not use: the set one tight hypothesis and every scan agreeing with the map at
  /// it (global_match.h's verify_agreement) while the robot turns this far or moves this far.
  /// A scan that disagrees starts the confirmation again; `confirm_strikes` of them reseed,
  /// searching wide even if the estimate fits best nearby (a look-alike seen from one side).
  /// The reseed's other places are carried along meanwhile (place_hypotheses.h): the estimate
  /// is not confirmed while one of them still agrees with the scans (`confirm_strikes`
  /// contradictions or trailing the best place's summed log-likelihood by `rival_margin` rule a
  /// place out), and an estimate whose place is ruled out, or is contradicted, hands over to them.
  double confirm_turn_rad = 4.7;
  double confirm_move_m = 3.0;
  int confirm_strikes = 3;
  double rival_margin = 30;
  /// The estimate is not confirmed while its own place (refined onto each scan) lies farther
  /// than this from it; after `confirm_strikes` such scans fresh particles are drawn about it.
  double place_offset_m = 0.25;
  /// Places a reseed keeps (the best-scoring of those the beams confirm): among racks in rows
  /// the true place may score below several look-alikes in the view the kidnap left.
  int max_places = 16;
  int seed = 1;  ///< the filter's random numbers (deterministic per seed)
};

class ParticleLocalizer final : public PoseEstimator {
 public:
  /// `motion` gives the odometry's and gyro's noise and the health thresholds (the same values
  /// the EKF is told).
  ParticleLocalizer(const worlds::World& map, const MapRaycaster& raycaster,
                    const EkfParams& motion, const GlobalMatchParams& global,
                    const ParticleParams& params);

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
    return motion_.learn_noise ? range_learnt_.sigma(motion_.range_sigma_m) : motion_.range_sigma_m;
  }
  LocalizationHealth health() const override { return health_; }
  int failed_matches() const override { return failed_matches_; }
  bool lost_in_view() const override { return health_ == LocalizationHealth::kLost && unmatched_; }
  int relocalizations() const override { return relocalizations_; }

  /// A place a global match finds for a scan: the pose, its score and the spread of the poses
  /// about it that fit about as well (ScanMatch::spread).
  struct Place {
    geom::Pose2 pose;
    double score = 0;
    Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  };
  /// A pose and the gyro bias that particle assumes: a bias error turns the heading steadily,
  /// so each particle carries its own and the scans choose among them (as the EKF's state does).
  struct Particle {
    double x, y, yaw, bias, w;
  };
  /// The set after the last update (pending and deferred motion not applied), weights summing
  /// to one.
  const std::vector<Particle>& particles() const { return set_; }

 private:
  /// The motion since the last scan, in the frame of the pose it started from.
  struct Pending {
    geom::Pose2 delta;
    double moved_m = 0, turned_rad = 0, gyro_var = 0, time_s = 0;
  };
  /// `first` then `then`: the deltas composed, the rest summed.
  static Pending chain(const Pending& first, const Pending& then);
  /// The motion since the last scan, and any deferred before it, applied to the particles.
  void apply_motion();
  /// A settled filter between updates, as AMCL: the motion since the last scan is held back from
  /// the particles (applied with the next update, in one draw) and the estimate dead-reckoned.
  void defer_motion();
  /// Whether this scan may leave the particles alone: the filter is settled, no confirmation or
  /// redraw is pending and it has moved less than update_min_m and turned less than
  /// update_min_rad since it last weighed.
  bool may_defer() const;
  /// The scan's returns to weigh by, in the robot frame (none when too few are valid).
  void take_points(const LidarScan& scan);
  /// Weighs the set by them; returns the weighted mean per-beam likelihood (for w_fast/slow), or
  /// -1 when there are none.
  double weigh();
  void tabulate_log_likelihood();
  /// A return's log-likelihood at distance d from the nearest mapped surface (inline: asked for
  /// every beam of every particle).
  double log_likelihood(double d) const {
    const double u = std::min(1.0, d * d * per_reach_squared_) * kLogTableSize;
    const std::size_t i = std::min(static_cast<std::size_t>(u), kLogTableSize - 1);
    const double f = u - static_cast<double>(i);
    return log_table_[i] + f * (log_table_[i + 1] - log_table_[i]);
  }
  /// KLD resampling into n drawn by the weights, plus `fresh` about the candidate places (1: the
  /// set replaced by particles about them).
  void resample(const std::vector<Place>& candidates, double fresh);
  /// scratch_ = `count` copies of the set's particles, drawn by low-variance resampling.
  void systematic_draw(std::size_t count);
  /// The places a global match finds for the scan about the estimate that the beams confirm, or
  /// that the best place near the estimate is the estimate itself.
  struct Reseed {
    std::vector<Place> candidates;
    bool estimate_fits = false;  ///< or nothing fits anywhere: no evidence against it
  };
  Reseed reseed_candidates(const LidarScan& scan);
  /// The place matched again in a narrow window at full resolution (see the .cpp).
  Place polish(const LidarScan& scan, Place place) const;
  void summarise();
  void judge(const LidarScan& scan);
  /// The weighed returns' summed log-likelihood at `pose`.
  double points_log_likelihood(const geom::Pose2& pose);
  /// Share of the weighed returns within three sigmas of a mapped surface from `pose`.
  double explained_share(const geom::Pose2& pose) const;
  void update_health();
  /// One scan's part in confirming a reseeded estimate (`agree`: the scan's agreement with the
  /// map at it, none when too few beams judge) and in ruling out its rivals.
  void confirm(const LidarScan& scan, const std::optional<double>& agree);
  /// The scan's verdict on a place (refined onto the scan first, written back).
  PlaceHypotheses::Verdict judge_place(const LidarScan& scan, geom::Pose2& place);
  /// One reading at rest: the Kalman update of the set's bias.
  void update_bias(double gyro_yaw_rate_radps);
  /// bias_ and bias_var_ from the set.
  void bias_moments();
  double normal(double sigma);

  const MapRaycaster& raycaster_;
  EkfParams motion_;
  GlobalMatchParams global_;
  ParticleParams p_;
  const worlds::World& map_;
  std::shared_ptr<const LikelihoodField> field_;  // shared among episodes on the same map
  std::optional<ScanMatcher> matcher_;  // for reseeding, built the first time it is needed
  util::RandomStream rng_;
  std::vector<Particle> set_, scratch_;
  std::vector<geom::Vec2> points_;  // the weighed beams' returns in the robot frame
  double hit_sigma_m_ = 0;          // the likelihood's sigma for them
  double weigh_sigma_m_ = 0;        // and the one they are weighed with (wider while unsettled)
  static constexpr std::size_t kLogTableSize = 4096;
  std::vector<double> log_table_;  // log-likelihood against the squared distance
  double tabulated_sigma_m_ = -1;
  double per_reach_squared_ = 1;  // 1 / (the field's reach)^2, the table's scale
  Pending pending_;
  Pending deferred_;  // motion of earlier scans not yet applied to the particles
  double since_weigh_m_ = 0, since_weigh_rad_ = 0;
  geom::Pose2 estimate_;  // best cluster's mean, at the last scan
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Zero();
  double bias_ = 0, bias_var_ = 0;  // the set's mean bias and its variance
  LearntVariance range_learnt_;
  GyroRestNoise gyro_learnt_;
  std::vector<double> residuals_;
  double w_slow_ = 0, w_fast_ = 0;
  int failed_matches_ = 0;
  LocalizationHealth health_ = LocalizationHealth::kOk;
  bool unmatched_ = false;
  double next_reseed_s_ = 0;
  int reseed_backoff_ = 1;  // periods between searches
  int relocalizations_ = 0;
  struct Confirmation {
    bool active = false;
    double turned_rad = 0, moved_m = 0;
    int strikes = 0;
    int offset_scans = 0;  // scans in a row the estimate's own place lay off it
  };
  Confirmation confirm_;
  std::optional<Place> nudge_;    // fresh particles to draw about the estimate's own place
  PlaceHypotheses places_;        // the last reseed's places, until the scans rule them out
  std::vector<Place> handover_;   // rivals still agreeing when the estimate was contradicted
  double last_share_ = -1;        // the last scan's explained share at the estimate
  int last_returns_ = 0;          // and its valid returns
  int view_changed_scans_ = 0;    // unexplained scans since the view changed at once
  bool estimate_agrees_ = false;  // the last scan agreed with the map at the estimate
  bool doubted_ = false;  // the confirmation failed: the next search does not trust the estimate
};

}  // namespace plantsim::robot
