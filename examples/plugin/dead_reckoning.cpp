// Integration of odometry and gyro, with a growing covariance (see the header).
#include "dead_reckoning.h"

#include <cmath>

namespace example {

using plantsim::robot::LocalizationHealth;
using plantsim::robot::PoseEstimator;

namespace {

class DeadReckoning : public PoseEstimator {
 public:
  DeadReckoning(plantsim::geom::Pose2 start, double distance_noise, double yaw_noise_per_s,
                double degraded_sigma_m)
      : pose_(start),
        distance_noise_(distance_noise),
        yaw_noise_per_s_(yaw_noise_per_s),
        degraded_sigma_m_(degraded_sigma_m) {}

  void predict(double distance_m, double gyro_yaw_rate_radps, double dt_s) override {
    const double mid_yaw = pose_.yaw + 0.5 * gyro_yaw_rate_radps * dt_s;
    pose_.x += distance_m * std::cos(mid_yaw);
    pose_.y += distance_m * std::sin(mid_yaw);
    pose_.yaw = std::atan2(std::sin(pose_.yaw + gyro_yaw_rate_radps * dt_s),
                           std::cos(pose_.yaw + gyro_yaw_rate_radps * dt_s));
    const double along = distance_noise_ * std::fabs(distance_m);
    yaw_var_ += yaw_noise_per_s_ * yaw_noise_per_s_ * dt_s;
    position_var_ += along * along + distance_m * distance_m * yaw_var_;
  }
  void standstill(double, double) override {}
  void observe(const plantsim::robot::LidarScan&) override {}
  void widen(double position_sigma_m, double yaw_sigma_rad) override {
    position_var_ += position_sigma_m * position_sigma_m;
    yaw_var_ += yaw_sigma_rad * yaw_sigma_rad;
  }
  plantsim::geom::Pose2 pose() const override { return pose_; }
  Eigen::Matrix3d pose_covariance() const override {
    Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
    c(0, 0) = c(1, 1) = position_var_;
    c(2, 2) = yaw_var_;
    return c;
  }
  double position_sigma_m() const override { return std::sqrt(position_var_); }
  double yaw_sigma_rad() const override { return std::sqrt(yaw_var_); }
  double gyro_bias_radps() const override { return 0; }
  double range_sigma_m() const override { return 0.02; }
  LocalizationHealth health() const override {
    return position_sigma_m() > degraded_sigma_m_ ? LocalizationHealth::kDegraded
                                                  : LocalizationHealth::kOk;
  }
  int failed_matches() const override { return 0; }
  bool lost_in_view() const override { return false; }
  int relocalizations() const override { return 0; }

 private:
  plantsim::geom::Pose2 pose_;
  double distance_noise_, yaw_noise_per_s_, degraded_sigma_m_;
  double position_var_ = 1e-6, yaw_var_ = 1e-6;
};

}  // namespace

plantsim::robot::EstimatorEntry dead_reckoning_entry() {
  using plantsim::util::ParamKind;
  plantsim::robot::EstimatorEntry e;
  e.name = "dead-reckoning";
  e.summary = "encoders and gyro integrated, the lidar unused (an example plugin)";
  e.params = {
      {"dead-reckoning", "distance_noise", ParamKind::kReal, 0.02, 0.0, 1.0, false,
       "1-sigma error per metre driven"},
      {"dead-reckoning", "yaw_noise_per_sqrt_s", ParamKind::kReal, 0.002, 0.0, 1.0, false,
       "heading random walk (rad/sqrt(s))"},
      {"dead-reckoning", "degraded_sigma_m", ParamKind::kReal, 0.3, 0.0, 100.0, true,
       "reports degraded beyond this 1-sigma (m)"},
  };
  e.make = [](const plantsim::robot::EstimatorContext& c,
              const plantsim::util::ParamValues& v) -> std::unique_ptr<PoseEstimator> {
    return std::make_unique<DeadReckoning>(c.start, v.real("dead-reckoning.distance_noise"),
                                           v.real("dead-reckoning.yaw_noise_per_sqrt_s"),
                                           v.real("dead-reckoning.degraded_sigma_m"));
  };
  return e;
}

}  // namespace example
