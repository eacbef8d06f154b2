// Prediction, the iterated scan update and health.
#include "sim/ekf_localizer.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace plantsim::sim {

std::string_view to_string(LocalizationHealth h) {
  switch (h) {
    case LocalizationHealth::kOk: return "ok";
    case LocalizationHealth::kDegraded: return "degraded";
    case LocalizationHealth::kLost: return "lost";
  }
  return "unknown";
}

EkfLocalizer::EkfLocalizer(EkfParams params, const geom::Pose2& initial_pose, const MapRaycaster& map)
    : p_(params), map_(map) {
  x_ << initial_pose.x, initial_pose.y, initial_pose.yaw, 0.0;
  P_.setZero();
  P_.diagonal() << p_.initial_position_sigma_m * p_.initial_position_sigma_m,
      p_.initial_position_sigma_m * p_.initial_position_sigma_m, p_.initial_yaw_sigma_rad * p_.initial_yaw_sigma_rad,
      p_.initial_bias_sigma_radps * p_.initial_bias_sigma_radps;
}

double EkfLocalizer::position_sigma_m() const {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(P_.topLeftCorner<2, 2>());
  return std::sqrt(std::max(es.eigenvalues().maxCoeff(), 0.0));
}

void EkfLocalizer::predict(double distance_m, double gyro_yaw_rate_radps, double dt_s) {
  if (dt_s <= 0) return;
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
      std::pow(p_.gyro_noise_radps * dt_s, 2);
  P_ = F * P_ * F.transpose() + G * q.asDiagonal() * G.transpose();
  P_(3, 3) += p_.bias_walk_radps_per_sqrt_s * p_.bias_walk_radps_per_sqrt_s * dt_s;
  update_health();
}

void EkfLocalizer::update_health() {
  // Five failed matches in a row (a third of a second at 15 Hz) is more than a passing crowd.
  if (position_sigma_m() > p_.lost_position_sigma_m) health_ = LocalizationHealth::kLost;
  else if (failed_matches_ >= 5) health_ = LocalizationHealth::kDegraded;
  else health_ = LocalizationHealth::kOk;
}

void EkfLocalizer::widen(double position_sigma_m, double yaw_sigma_rad) {
  P_(0, 0) += position_sigma_m * position_sigma_m;
  P_(1, 1) += position_sigma_m * position_sigma_m;
  P_(2, 2) += yaw_sigma_rad * yaw_sigma_rad;
}

double EkfLocalizer::correct(const LidarScan& scan) {
  // Beams spread evenly over the scan; the same ones in every iteration.
  std::vector<std::size_t> beams;
  const std::size_t n = scan.ranges.size();
  const std::size_t stride = std::max<std::size_t>(1, n / static_cast<std::size_t>(std::max(1, p_.beams_used)));
  for (std::size_t i = 0; i < n; i += stride)
    if (scan.valid(i)) beams.push_back(i);
  if (beams.empty()) return 0.0;

  const State x0 = x_;
  const Covariance P0 = P_;
  const Covariance P0_inv = P0.inverse();
  const double r_var = p_.range_sigma_m * p_.range_sigma_m;
  State xi = x0;
  Covariance info;
  int used = 0;
  for (int iter = 0; iter < std::max(1, p_.iterations); ++iter) {
    info = P0_inv;
    // Minimises the prior's and the beams' squared errors about this iterate:
    // (P0^-1 + sum H'H/r) dx = P0^-1 (x0 - xi) + sum H' innovation / r.
    State dx = x0 - xi;
    dx(2) = geom::wrap_angle(dx(2));
    State eta = P0_inv * dx;
    used = 0;
    const geom::Pose2 robot{xi(0), xi(1), xi(2)};
    const geom::Pose2 sensor = geom::compose(robot, scan.mount);
    const geom::Vec2 mount_world = geom::rotate({scan.mount.x, scan.mount.y}, robot.yaw);
    for (std::size_t i : beams) {
      const double phi = sensor.yaw + scan.angle(i);
      const auto hit = map_.cast(sensor.position(), phi, scan.max_range_m);
      if (!hit) continue;
      const geom::Vec2 u = geom::unit_from_angle(phi);
      const double nu = geom::dot(hit->normal, u);
      if (-nu < p_.min_incidence_cos) continue;  // grazing: the range jumps with the pose
      // Point-to-line: r = n.(q - s) / (n.u); dr/ds = -n / (n.u), dr/dphi = -r (n.u') / (n.u).
      const geom::Vec2 dr_ds = (-1.0 / nu) * hit->normal;
      const geom::Vec2 u_perp{-u.y, u.x};
      const double dr_dphi = -hit->range_m * geom::dot(hit->normal, u_perp) / nu;
      Eigen::RowVector4d H;
      H << dr_ds.x, dr_ds.y, geom::dot(dr_ds, {-mount_world.y, mount_world.x}) + dr_dphi, 0.0;
      const double innovation = scan.ranges[i] - hit->range_m;
      // Gate against the prior's spread, moved to this iterate.
      const double s = (H * P0 * H.transpose())(0, 0) + r_var;
      if (innovation * innovation > p_.gate_chi2 * s) continue;
      info += H.transpose() * H / r_var;
      eta += H.transpose() * innovation / r_var;
      ++used;
    }
    if (used < 3) break;
    const State step = info.ldlt().solve(eta);
    xi += step;
    xi(2) = geom::wrap_angle(xi(2));
    if (step.head<2>().norm() < 1e-4 && std::fabs(step(2)) < 1e-5) break;
  }
  const double inliers = static_cast<double>(used) / static_cast<double>(beams.size());
  if (used >= 3 && inliers >= p_.degraded_inlier_fraction) {
    x_ = xi;
    P_ = info.inverse();
    P_ = 0.5 * (P_ + P_.transpose());
    failed_matches_ = 0;
  } else {
    ++failed_matches_;
  }
  update_health();
  return inliers;
}

}  // namespace plantsim::sim
