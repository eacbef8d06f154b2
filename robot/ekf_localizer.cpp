// Prediction, the iterated scan update and health.
#include "robot/ekf_localizer.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "robot/median_spread.h"

namespace plantsim::robot {

EkfLocalizer::EkfLocalizer(EkfParams params, const geom::Pose2& initial_pose,
                           const MapRaycaster& map)
    : p_(params),
      range_learnt_(params.range_learning_rate),
      gyro_learnt_(params.gyro_learning_rate, params.gyro_min_samples),
      map_(map) {
  x_ << initial_pose.x, initial_pose.y, initial_pose.yaw, 0.0;
  P_.setZero();
  P_.diagonal() << p_.initial_position_sigma_m * p_.initial_position_sigma_m,
      p_.initial_position_sigma_m * p_.initial_position_sigma_m,
      p_.initial_yaw_sigma_rad * p_.initial_yaw_sigma_rad,
      p_.initial_bias_sigma_radps * p_.initial_bias_sigma_radps;
}

double EkfLocalizer::range_sigma_m() const {
  return p_.learn_noise ? range_learnt_.sigma(p_.range_sigma_m) : p_.range_sigma_m;
}

double EkfLocalizer::gyro_noise_radps() const {
  return p_.learn_noise ? gyro_learnt_.sigma(p_.gyro_noise_radps) : p_.gyro_noise_radps;
}

double EkfLocalizer::position_sigma_m() const {
  // Eigen's closed form for a 2 x 2 (the iterative solver cost 2 % of an episode), and only when
  // the block has changed since the last answer.
  if (P_(0, 0) == sigma_of_[0] && P_(1, 0) == sigma_of_[1] && P_(0, 1) == sigma_of_[2] &&
      P_(1, 1) == sigma_of_[3])
    return sigma_;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es;
  es.computeDirect(P_.topLeftCorner<2, 2>(), Eigen::EigenvaluesOnly);
  sigma_of_[0] = P_(0, 0), sigma_of_[1] = P_(1, 0), sigma_of_[2] = P_(0, 1),
  sigma_of_[3] = P_(1, 1);
  sigma_ = std::sqrt(std::max(es.eigenvalues().maxCoeff(), 0.0));
  return sigma_;
}

void EkfLocalizer::predict(double distance_m, double gyro_yaw_rate_radps, double dt_s) {
  if (dt_s <= 0) return;
  gyro_learnt_.reading();  // standstill() right after this one: two readings in a row at rest
  const double turn = (gyro_yaw_rate_radps - x_(3)) * dt_s;
  const double mid = x_(2) + 0.5 * turn;
  const double c = std::cos(mid), s = std::sin(mid);
  x_(0) += distance_m * c;
  x_(1) += distance_m * s;
  x_(2) = geom::wrap_angle(x_(2) + turn);

  Covariance F = Covariance::Identity();
  F(0, 2) = -distance_m * s;
  F(1, 2) = distance_m * c;
  F(0, 3) = 0.5 * distance_m * s * dt_s;
  F(1, 3) = -0.5 * distance_m * c * dt_s;
  F(2, 3) = -dt_s;
  // Noise inputs: travel along, skid across, gyro white noise; the bias walks.
  Eigen::Matrix<double, 4, 3> G = Eigen::Matrix<double, 4, 3>::Zero();
  G(0, 0) = c;
  G(1, 0) = s;
  G(0, 1) = -s;
  G(1, 1) = c;
  G(0, 2) = -0.5 * distance_m * s;
  G(1, 2) = 0.5 * distance_m * c;
  G(2, 2) = 1.0;
  const double d = std::fabs(distance_m);
  Eigen::Vector3d q;
  // Tyres skid sideways when the robot turns while it moves (centripetal load), not otherwise.
  const double skid = p_.lateral_noise * std::min(std::fabs(turn), d / 0.1);
  q << std::pow(p_.distance_noise * d + 1e-4, 2), std::pow(skid + 1e-4, 2),
      std::pow(gyro_noise_radps() * dt_s, 2);
  P_ = F * P_ * F.transpose() + G * q.asDiagonal() * G.transpose();
  P_(3, 3) += p_.bias_walk_radps_per_sqrt_s * p_.bias_walk_radps_per_sqrt_s * dt_s;
  update_health();
}

void EkfLocalizer::update_health() {
  const double sigma = position_sigma_m();
  if (sigma > p_.lost_position_sigma_m || failed_matches_ >= p_.lost_failed_matches)
    health_ = LocalizationHealth::kLost;
  else if (sigma > p_.ok_position_sigma_m || inconsistent_ || failed_matches_ >= 5)
    health_ = LocalizationHealth::kDegraded;
  else
    health_ = LocalizationHealth::kOk;
}

void EkfLocalizer::record_nis(double nis, int dof) {
  const std::size_t window = static_cast<std::size_t>(std::max(1, p_.nis_window));
  if (nis_.size() < window)
    nis_.emplace_back(nis, dof);
  else
    nis_[nis_next_] = {nis, dof};
  nis_next_ = (nis_next_ + 1) % window;
  double sum = 0;
  int k = 0;
  for (const auto& [v, d] : nis_) sum += v, k += d;
  // Wilson-Hilferty: chi-square with k degrees of freedom is nearly k (1 - 2/9k + z sqrt(2/9k))^3.
  const double a = 2.0 / (9.0 * std::max(k, 1));
  const double bound = k * std::pow(1.0 - a + p_.nis_quantile_z * std::sqrt(a), 3);
  // A window of a few scans judges nothing yet.
  inconsistent_ = nis_.size() >= window / 2 && k > 0 && sum > bound;
  if (inconsistent_ && position_sigma_m() < 0.5 * p_.ok_position_sigma_m) {
    // The filter is surer than the scans allow (a gyro bias past its prior, a slip): widen the
    // pose and the bias so that the scans can pull them, and judge afresh. Only a tight
    // estimate is widened: innovations that stay inconsistent because the lidar is noisier than
    // the filter assumes must not inflate it without end (the status says degraded instead).
    P_.topLeftCorner<3, 3>() *= 2.0;
    P_.block<3, 1>(0, 3) *= 2.0;
    P_.block<1, 3>(3, 0) *= 2.0;
    P_(3, 3) *= 4.0;
    nis_.clear();
    nis_next_ = 0;
    ++inflations_;
  }
}

void EkfLocalizer::reset(const geom::Pose2& pose, const Eigen::Matrix3d& pose_covariance) {
  x_.head<3>() << pose.x, pose.y, pose.yaw;
  P_.topLeftCorner<3, 3>() = pose_covariance;
  P_.block<3, 1>(0, 3).setZero();
  P_.block<1, 3>(3, 0).setZero();
  failed_matches_ = 0;
  nis_.clear();
  nis_next_ = 0;
  inconsistent_ = false;
  update_health();
}

void EkfLocalizer::widen(double position_sigma_m, double yaw_sigma_rad) {
  P_(0, 0) += position_sigma_m * position_sigma_m;
  P_(1, 1) += position_sigma_m * position_sigma_m;
  P_(2, 2) += yaw_sigma_rad * yaw_sigma_rad;
}

void EkfLocalizer::widen_to_along(const Eigen::Vector2d& direction, double sigma_m) {
  const double variance = direction.dot(P_.topLeftCorner<2, 2>() * direction);
  if (variance >= sigma_m * sigma_m) return;
  P_.topLeftCorner<2, 2>() += (sigma_m * sigma_m - variance) * direction * direction.transpose();
  update_health();
}

namespace {

// Yaw is compared with positions at this lever arm: a yaw error of 1 rad moves a point this far
// away by about 1 m.
constexpr double kYawLever_m = 1.0;

/// The scan's information and gradient restricted to the directions it constrains to within
/// `sigma_m` (positions in metres, yaw at kYawLever_m); returns how many there are.
int keep_constrained(Eigen::Matrix4d& info, Eigen::Vector4d& gradient, double sigma_m) {
  const Eigen::Vector3d scale(1.0, 1.0, 1.0 / kYawLever_m);
  const Eigen::Matrix3d scaled =
      scale.asDiagonal() * info.topLeftCorner<3, 3>() * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(scaled);
  Eigen::Matrix3d projector = Eigen::Matrix3d::Zero();
  int kept = 0;
  for (int i = 0; i < 3; ++i) {
    if (es.eigenvalues()(i) < 1.0 / (sigma_m * sigma_m)) continue;
    projector += es.eigenvectors().col(i) * es.eigenvectors().col(i).transpose();
    ++kept;
  }
  // Back to the state's units (the scaling is diagonal: info = D^-1 info' D^-1, g = D^-1 g').
  const Eigen::Matrix3d kept_scaled = projector * scaled * projector;
  info.setZero();
  info.topLeftCorner<3, 3>() =
      scale.cwiseInverse().asDiagonal() * kept_scaled * scale.cwiseInverse().asDiagonal();
  Eigen::Vector3d g = scale.asDiagonal() * gradient.head<3>();
  g = projector * g;
  gradient.setZero();
  gradient.head<3>() = scale.cwiseInverse().asDiagonal() * g;
  return kept;
}

}  // namespace

bool EkfLocalizer::update_pose(const geom::Pose2& z, const Eigen::Matrix3d& r, double gate_chi2) {
  const Eigen::Vector3d innovation(z.x - x_(0), z.y - x_(1), geom::wrap_angle(z.yaw - x_(2)));
  const Eigen::Matrix3d s = P_.topLeftCorner<3, 3>() + r;
  const Eigen::LDLT<Eigen::Matrix3d> s_ldlt(s);
  if (s_ldlt.info() != Eigen::Success) return false;
  if (!(innovation.dot(s_ldlt.solve(innovation)) <= gate_chi2)) return false;
  // K = P H' S^-1 with H = [I 0]: the gain for the whole state (the bias through its correlation).
  const Eigen::Matrix<double, 4, 3> gain = s_ldlt.solve(P_.topRows<3>()).transpose();
  x_ += gain * innovation;
  x_(2) = geom::wrap_angle(x_(2));
  P_ -= gain * P_.topRows<3>();
  P_ = 0.5 * (P_ + P_.transpose());
  update_health();
  return true;
}

void EkfLocalizer::standstill(double gyro_yaw_rate_radps, double dt_s) {
  if (dt_s <= 0) return;
  const double noise = gyro_noise_radps();
  if (!at_rest(gyro_yaw_rate_radps - x_(3), noise * noise + P_(3, 3)))
    return predict(0.0, gyro_yaw_rate_radps, dt_s);
  gyro_learnt_.reading();
  P_(3, 3) += p_.bias_walk_radps_per_sqrt_s * p_.bias_walk_radps_per_sqrt_s * dt_s;
  // z = bias + white noise: H = [0 0 0 1], R = the gyro's noise per reading. At rest two
  // readings in a row differ by the noise alone (the bias cancels, whatever its estimate): half
  // their squared difference is learnt as the noise's variance, and the readings wait for it.
  if (!p_.learn_noise) {
    update_bias(gyro_yaw_rate_radps);
  } else {
    gyro_learnt_.at_rest(gyro_yaw_rate_radps);
    for (const double z : gyro_learnt_.take_readings()) update_bias(z);
  }
  update_health();
}

void EkfLocalizer::update_bias(double gyro_yaw_rate_radps) {
  const double r = gyro_noise_radps() * gyro_noise_radps();
  const double s = P_(3, 3) + r;
  if (!(s > 0)) return;
  const State k = P_.col(3) / s;
  x_ += k * (gyro_yaw_rate_radps - x_(3));
  x_(2) = geom::wrap_angle(x_(2));
  P_ -= k * P_.row(3);
  P_ = 0.5 * (P_ + P_.transpose());
}

void EkfLocalizer::associate(const LidarScan& scan, const State& x, std::size_t stride) {
  faces_.clear();
  const geom::Pose2 matched_from = geom::compose({x(0), x(1), x(2)}, scan.mount);
  const BeamDirections::Turned all = directions_.turned(scan, matched_from.yaw);
  fan_.clear();
  for (std::size_t i = 0; i < scan.ranges.size(); i += stride) fan_.push_back(all[i]);
  map_.cast_fan(matched_from.position(), fan_, matched_from.yaw + scan.angle(0),
                static_cast<double>(stride) * scan.angle_increment_rad, scan.max_range_m, hits_);
  for (std::size_t k = 0; k < fan_.size(); ++k)
    if (scan.valid(k * stride) && hits_[k])
      faces_.push_back({k * stride, hits_[k]->point, hits_[k]->normal});
}

EkfLocalizer::ScanTerms EkfLocalizer::scan_terms(const LidarScan& scan, const State& xi,
                                                 const Covariance& P0) {
  ScanTerms terms;
  Covariance& scan_info = terms.info;
  State& gradient = terms.gradient;
  int& used = terms.used;
  int& expected = terms.expected;
  const double r_var = r_var_;
  residuals_.clear();
  const geom::Pose2 robot{xi(0), xi(1), xi(2)};
  const geom::Pose2 sensor = geom::compose(robot, scan.mount);
  const geom::Vec2 mount_world = geom::rotate({scan.mount.x, scan.mount.y}, robot.yaw);
  const BeamDirections::Turned directions = directions_.turned(scan, sensor.yaw);
  for (const Face& f : faces_) {
    const geom::Vec2 u = directions[f.beam];
    const double nu = geom::dot(f.normal, u);
    if (-nu < p_.min_incidence_cos) continue;  // grazing: the range jumps with the pose
    const double predicted = geom::dot(f.normal, f.point - sensor.position()) / nu;
    if (!(predicted > 0)) continue;
    // Point-to-line: r = n.(q - s) / (n.u); dr/ds = -n / (n.u), dr/dphi = -r (n.u') / (n.u).
    const geom::Vec2 dr_ds = (-1.0 / nu) * f.normal;
    const geom::Vec2 u_perp{-u.y, u.x};
    const double dr_dphi = -predicted * geom::dot(f.normal, u_perp) / nu;
    Eigen::RowVector4d H;
    H << dr_ds.x, dr_ds.y, geom::dot(dr_ds, {-mount_world.y, mount_world.x}) + dr_dphi, 0.0;
    const double innovation = scan.ranges[f.beam] - predicted;
    // Gate against the prior's spread, moved to this iterate.
    const double s = (H * P0 * H.transpose())(0, 0) + r_var;
    const bool outlier =
        innovation * innovation > std::max(p_.gate_chi2 * s, p_.gate_floor_m * p_.gate_floor_m);
    // A return short of the mapped face: something the map lacks stands in front of it (a
    // box, a person). It neither confirms the map nor contradicts it (the beam model's
    // "unexpected object"); only a return from beyond a mapped face contradicts it. Counted
    // against the match, a box beside the robot in an open yard would fail every scan.
    if (outlier && innovation < 0) continue;
    ++expected;
    if (outlier) continue;
    // H' H / r and H' innovation / r on the pose block only, each term as Eigen's outer product
    // forms it (H_i H_j, then / r), so the sums are the same bit for bit: H's bias entry is zero,
    // so the bias row and column only ever added zeros, and H_i H_j = H_j H_i exactly (ten of
    // the sixteen divisions were repeats or zeros).
    for (int i = 0; i < 3; ++i) {
      for (int j = i; j < 3; ++j) scan_info(i, j) += H(i) * H(j) / r_var;
      gradient(i) += H(i) * innovation / r_var;
    }
    residuals_.emplace_back(innovation, s - r_var);
    ++used;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) scan_info(j, i) = scan_info(i, j);
  return terms;
}

void EkfLocalizer::check_consistency(const State& x0, const Covariance& P0, int kept) {
  // Consistency: the correction against the spread the prior and the update predict for it,
  // dx' (P0 - P1)^+ dx, chi-square with as many degrees of freedom as directions updated.
  State correction = x_ - x0;
  correction(2) = geom::wrap_angle(correction(2));
  const Eigen::Matrix3d spread = (P0 - P_).topLeftCorner<3, 3>();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(spread);
  const Eigen::Vector3d along = es.eigenvectors().transpose() * correction.head<3>();
  double nis = 0;
  int dof = 0;
  const double floor = 1e-9 * std::max(es.eigenvalues().maxCoeff(), 1e-12);
  for (int i = 0; i < 3; ++i)
    if (es.eigenvalues()(i) > floor) nis += along(i) * along(i) / es.eigenvalues()(i), ++dof;
  dof = std::min(dof, kept);
  if (dof > 0) record_nis(nis, dof);
}

namespace {

// After the first step the beams are matched again from the new pose, unless it moved less than
// a millimetre and 1e-4 rad (2 mm at 20 m): the second fan cost a tenth of a sensing episode, and
// from so near it matched differently in one such scan in fifty (world_N200), a few beams at a
// face's edge, where the faces either side predict nearly the same range or so different a one
// that the gate drops the beam.
bool moved_past_an_edge(const EkfLocalizer::State& from, const EkfLocalizer::State& to) {
  constexpr double kStillM = 1e-3, kStillRad = 1e-4;
  return std::hypot(to(0) - from(0), to(1) - from(1)) > kStillM ||
         std::fabs(geom::wrap_angle(to(2) - from(2))) > kStillRad;
}

}  // namespace

EkfLocalizer::Fit EkfLocalizer::fit(const LidarScan& scan, const State& x0, const Covariance& P0,
                                    const Covariance& P0_inv, std::size_t stride) {
  associate(scan, x0, stride);
  Fit f{x0, {}, 0};
  for (int iter = 0; iter < std::max(1, p_.iterations); ++iter) {
    // Minimises the prior's and the beams' squared errors about this iterate:
    // (P0^-1 + sum H'H/r) dx = P0^-1 (x0 - xi) + sum H' innovation / r,
    // the beams' terms kept only along the directions they constrain.
    if (iter == 1 && moved_past_an_edge(x0, f.x)) associate(scan, f.x, stride);
    State dx = x0 - f.x;
    dx(2) = geom::wrap_angle(dx(2));
    f.terms = scan_terms(scan, f.x, P0);
    if (f.terms.expected < p_.min_informative_beams || f.terms.used < 3) break;
    f.kept = keep_constrained(f.terms.info, f.terms.gradient, p_.constraint_sigma_m);
    if (f.kept == 0) break;
    const Covariance info = P0_inv + f.terms.info;
    const State step = info.ldlt().solve(P0_inv * dx + f.terms.gradient);
    f.x += step;
    f.x(2) = geom::wrap_angle(f.x(2));
    if (step.head<2>().norm() < 1e-4 && std::fabs(step(2)) < 1e-5) break;
  }
  return f;
}

double EkfLocalizer::post_fit_variance() const {
  // The residuals at the fit's last iterate, one step (its last) from the answer: computing them
  // again at the answer cost a twentieth of a sensing episode.
  if (residuals_.size() < 10) return -1;
  // Median absolute deviation about the median, scaled to a Gaussian's sigma: beams on things
  // the map lacks do not inflate it. After the fit the residuals are smaller than the noise by
  // the three directions fitted (n / (n - 3)); before it they carry the prior's error, common
  // to every beam, which no per-beam statistic can tell from noise.
  std::vector<double>& r = scratch_;
  r.clear();
  for (const auto& [innovation, spread] : residuals_) r.push_back(innovation);
  const double sigma = 1.4826 * median_spread(r).mad;
  const double n = static_cast<double>(r.size());
  return sigma * sigma * n / (n - 3.0);
}

double EkfLocalizer::correct(const LidarScan& scan) {
  // Beams spread evenly over the scan, each matched to the mapped face it meets from the prior
  // pose by one fan of ray casts; the iterations move the pose against those faces' lines, as a
  // point-to-plane match does. The match is made once more after the first step, from a pose
  // near the answer: a beam that a centimetre of error sends past a box's edge at 17 m would
  // otherwise pull every later step (test_perception's consistency test sees it).
  const std::size_t n = scan.ranges.size();
  const std::size_t stride =
      std::max<std::size_t>(1, n / static_cast<std::size_t>(std::max(1, p_.beams_used)));
  const State x0 = x_;
  const Covariance P0 = P_;
  const Covariance P0_inv = P0.inverse();
  r_var_ = range_sigma_m() * range_sigma_m();
  Fit f = fit(scan, x0, P0, P0_inv, stride);
  auto accepted = [&](const Fit& g) {
    return g.terms.expected >= p_.min_informative_beams && g.terms.used >= 3 && g.kept > 0 &&
           static_cast<double>(g.terms.used) / static_cast<double>(g.terms.expected) >=
               p_.degraded_inlier_fraction;
  };
  double learnt = -1;  // this scan's noise variance, from its residuals after the fit
  if (p_.learn_noise && accepted(f)) {
    learnt = post_fit_variance();
    // The first scans, before anything is learnt: a scan that shows noise clearly above the
    // told value is fitted again with it, so that the filter is never more confident than its
    // own first scans allow (a told value three times too small made it so for seconds).
    constexpr int kWarmUpScans = 10;
    if (range_learnt_.samples() < kWarmUpScans && learnt > kClearlyAbove * kClearlyAbove * r_var_) {
      r_var_ = learnt;
      f = fit(scan, x0, P0, P0_inv, stride);
      learnt = accepted(f) ? post_fit_variance() : -1;
    }
  }
  const ScanTerms& terms = f.terms;
  informative_ = terms.expected >= p_.min_informative_beams;
  if (!informative_) {
    // Open ground: nothing to match. Odometry and the gyro carry the estimate on.
    constrained_ = 0;
    update_health();
    return 0.0;
  }
  const double inliers = static_cast<double>(terms.used) / static_cast<double>(terms.expected);
  if (accepted(f)) {
    x_ = f.x;
    P_ = (P0_inv + terms.info).inverse();
    P_ = 0.5 * (P_ + P_.transpose());
    constrained_ = f.kept;
    failed_matches_ = 0;
    check_consistency(x0, P0, f.kept);
    if (learnt >= 0) {  // learnt from the scans the map explained only
      range_learnt_.add(learnt);
    }
  } else if (f.kept > 0 || terms.used < 3) {
    ++failed_matches_;
  }
  update_health();
  return inliers;
}

}  // namespace plantsim::robot
