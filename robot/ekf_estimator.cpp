// The EKF's scan handling: the local update, and the global match when the estimate is wide.
#include "robot/ekf_estimator.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace plantsim::robot {

EkfEstimator::EkfEstimator(const worlds::World& map, const MapRaycaster& raycaster,
                           const EkfParams& ekf, const GlobalMatchParams& global)
    : map_(map),
      raycaster_(raycaster),
      p_(global),
      lost_sigma_m_(ekf.lost_position_sigma_m),
      ekf_(ekf, map.start, raycaster) {}

void EkfEstimator::observe(const LidarScan& scan) {
  if (relocalize(scan)) ekf_.correct(scan);
}

// A measured pose within this normalised distance of the estimate (chi-square, 3 degrees of
// freedom, 0.999) updates it; farther, it is a look-alike the window happened to hold.
constexpr double kPoseGateChi2 = 16.27;
// A reset's position sigma at most this share of the sigma that would trigger another match.
constexpr double kResetSigmaShare = 0.9;
constexpr double kResetMinYawSigmaRad = 0.01;
// The global match's window: this many of the estimate's sigmas.
constexpr double kWindowSigmas = 3.0;

void EkfEstimator::keep_look_alikes_in_window(const ScanMatch& m) {
  // The same ambiguity is matched again every period, each time as if new: the estimate
  // narrows, its window (three sigmas) with it, the look-alikes leave the window and the
  // ambiguity reads as certainty (seen on a tuning yard: pulled 2 m off, then `ok` there for
  // 100 s). Until a match tells the places apart, the estimate stays wide enough that its
  // window holds them.
  for (const auto& [place, score] : m.alternatives) {
    const Eigen::Vector2d offset(place.x - m.pose.x, place.y - m.pose.y);
    const double apart = offset.norm();
    if (apart < 1e-9) continue;  // the best itself, or a place apart in heading only
    ekf_.widen_to_along(offset / apart, apart / kWindowSigmas);
  }
}

Eigen::Matrix3d reset_covariance(const Eigen::Matrix3d& spread, double cell_m, double max_sigma_m,
                                 double min_yaw_sigma_rad) {
  const double most = std::max(max_sigma_m, cell_m);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(spread.topLeftCorner<2, 2>());
  const Eigen::Vector2d variances =
      es.eigenvalues().cwiseMax(cell_m * cell_m).cwiseMin(most * most);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  covariance.topLeftCorner<2, 2>() =
      es.eigenvectors() * variances.asDiagonal() * es.eigenvectors().transpose();
  covariance(2, 2) = std::max(spread(2, 2), min_yaw_sigma_rad * min_yaw_sigma_rad);
  return covariance;
}

void EkfEstimator::place(const ScanMatch& m) {
  // A match the estimate already holds within its uncertainty is evidence to fuse, not a place
  // to restart from: a restart forgets what the estimate knew along the directions the scan
  // leaves nearly open (seen on a tuning yard: lost by its spread alone, 1 cm off, the robot was
  // restarted 0.29 m off by a match on a lone wall at 12 m and drove 160 s along it that far
  // off, reporting itself degraded, not lost). The match's spread is floored at the grid's cell,
  // not capped: where it is open, the estimate keeps its own.
  if (ekf_.update_pose(
          m.pose,
          reset_covariance(m.spread, matcher_->resolution_m(),
                           std::numeric_limits<double>::infinity(), kResetMinYawSigmaRad),
          kPoseGateChi2))
    return;
  // The spread of the poses that fit about as well, not the grid's step alone: a match on a few
  // returns can sit cells off, mostly along what it leaves open, and a heading a degree off
  // held at a third of that sends the robot across open ground sideways (seen on a sparse
  // plant, very wet: a reset 0.16 m off at a 0.1 m sigma, the robot then driving up to 0.9 m
  // off). The position's spread is capped below the sigma at which the filter would call
  // itself lost or match again: a wider one would only repeat the match, scan after scan.
  ekf_.reset(m.pose,
             reset_covariance(m.spread, matcher_->resolution_m(),
                              kResetSigmaShare * std::min(p_.global_match_sigma_m, lost_sigma_m_),
                              kResetMinYawSigmaRad));
  ++relocalizations_;
}

bool EkfEstimator::relocalize(const LidarScan& scan) {
  const double sigma = ekf_.position_sigma_m();
  if (sigma <= p_.global_match_sigma_m) {
    unmatched_ = false;
    return true;
  }
  const bool local_ok = sigma <= p_.local_update_max_sigma_m;
  if (scan.t_s + 1e-9 < next_match_s_) return local_ok;
  next_match_s_ = scan.t_s + p_.global_match_period_s;
  if (!matcher_) matcher_.emplace(map_, p_.matcher);
  const MatchWindow window{std::clamp(kWindowSigmas * sigma, 0.5, p_.global_match_max_window_m),
                           std::clamp(3.0 * ekf_.yaw_sigma_rad(), 0.05, M_PI)};
  const int returns = valid_returns(scan);
  if (returns < p_.global_match_min_returns) return local_ok;  // open ground: nothing to match
  const std::optional<ScanMatch> m = matcher_->match(scan, ekf_.pose(), window);
  if (!m) return local_ok;
  if (m->score * returns < p_.global_match_min_returns) {
    // Even at its best pose the scan has too few returns on the map to judge by (what it sees
    // is mostly things the map lacks: unmapped boxes, people, on open ground): no evidence
    // either way. It goes on, as on open ground.
    unmatched_ = false;
    return local_ok;
  }
  // Confirmed: enough beams read what the map predicts from the pose; contradicted: enough pass
  // where it has surfaces; neither: too few beams meet a mapped surface to tell.
  auto confirmed = [&](const std::optional<double>& a) { return a && *a >= p_.verify_agreement; };
  const std::optional<double> agree =
      scan_agreement(raycaster_, scan, m->pose, p_.verify_tolerance_m);
  const bool contradicted = agree && *agree < p_.verify_agreement;
  const bool placed = m->accepted && !contradicted;
  // Not placed, yet nothing contradicts the estimate: the returns fit the map well in more than
  // one place of the window (a long wall seen alone), or their fit is weak only because many
  // fall on things the map lacks while the best pose reads, beam by beam, what the map predicts
  // (boxes beside the robot in an open yard), or the estimate itself reads what the map predicts
  // (its spread grew over open ground while it stayed right, and what is now in view, a wall's
  // end and boxes the map lacks, places the robot nowhere). There is only too little to place
  // the robot: it goes on (slowly, by its uncertainty) towards what will tell the places apart,
  // and the window is not widened, which would only add look-alikes.
  const bool undecided = !m->accepted && (m->score >= p_.matcher.min_score || !contradicted);
  if (!placed && (undecided || confirmed(scan_agreement(raycaster_, scan, ekf_.pose(),
                                                        p_.verify_tolerance_m)))) {
    unmatched_ = false;
    // Ambiguous is not uninformative: a lone wall with its end in view leaves the estimate
    // open along the wall, yet pins it across the wall and in heading. A match that fits well
    // and reads, beam by beam, what the map predicts updates the estimate with the spread of its
    // near-best poses: in the directions they agree on, not in those they leave open. (Seen:
    // the matcher's best pose within 0.2 m of the truth for 10 s beside a wall's end while the
    // estimate, 2.5 m off after open ground, went on blind and the episode failed.)
    if (m->score >= p_.matcher.min_score && confirmed(agree) &&
        ekf_.update_pose(m->pose, m->spread, kPoseGateChi2))
      keep_look_alikes_in_window(*m);
    return ekf_.position_sigma_m() <= p_.local_update_max_sigma_m;
  }
  unmatched_ = !placed;
  if (unmatched_) {
    // Returns, but no place that fits them alone: search wider next time.
    if (!local_ok && kWindowSigmas * sigma < p_.global_match_max_window_m)
      ekf_.widen(0.5 * sigma, 0.0);
    return local_ok;
  }
  place(*m);
  return true;  // the local update refines the match
}

}  // namespace plantsim::robot
