// The guards: a plugin's factories inside a try; its estimators wrapped, each call inside a try;
// its local controllers marked with their origin (the path follower catches around its calls,
// which costs nothing while nothing throws). Any exception leaves as a ComponentFailure that says
// whose it was.
#include "plugins/guarded_components.h"

#include <exception>
#include <utility>

#include "util/component_failure.h"

namespace plantsim::plugins {

namespace {

// Each call forwarded inside a try; what it throws leaves as a ComponentFailure.
#define PLANTSIM_GUARDED(call)                \
  try {                                       \
    return call;                              \
  } catch (...) {                             \
    util::rethrow_as_component_failure(who_); \
  }

class GuardedEstimator : public robot::PoseEstimator {
 public:
  GuardedEstimator(std::unique_ptr<robot::PoseEstimator> inner, std::string who)
      : inner_(std::move(inner)), who_(std::move(who)) {}
  void predict(double d, double w, double dt) override {
    PLANTSIM_GUARDED(inner_->predict(d, w, dt))
  }
  void standstill(double w, double dt) override { PLANTSIM_GUARDED(inner_->standstill(w, dt)) }
  void observe(const robot::LidarScan& scan) override { PLANTSIM_GUARDED(inner_->observe(scan)) }
  void widen(double p, double y) override{PLANTSIM_GUARDED(inner_->widen(p, y))} geom::Pose2
      pose() const override{PLANTSIM_GUARDED(inner_->pose())} Eigen::Matrix3d
      pose_covariance() const override {
    PLANTSIM_GUARDED(inner_->pose_covariance())
  }
  double position_sigma_m() const override { PLANTSIM_GUARDED(inner_->position_sigma_m()) }
  double yaw_sigma_rad() const override { PLANTSIM_GUARDED(inner_->yaw_sigma_rad()) }
  double gyro_bias_radps() const override { PLANTSIM_GUARDED(inner_->gyro_bias_radps()) }
  double range_sigma_m() const override{
      PLANTSIM_GUARDED(inner_->range_sigma_m())} robot::LocalizationHealth health() const override {
    PLANTSIM_GUARDED(inner_->health())
  }
  int failed_matches() const override { PLANTSIM_GUARDED(inner_->failed_matches()) }
  bool lost_in_view() const override { PLANTSIM_GUARDED(inner_->lost_in_view()) }
  int relocalizations() const override { PLANTSIM_GUARDED(inner_->relocalizations()) }

 private:
  std::unique_ptr<robot::PoseEstimator> inner_;
  std::string who_;
};

/// Guards the factory; what it makes is wrapped by `wrap`.
template <typename Entry, typename Wrap>
void guard_factory(Entry& e, const std::string& who, Wrap wrap) {
  auto make = std::move(e.make);
  e.make = [make, who, wrap](const auto& context, const util::ParamValues& values) {
    decltype(make(context, values)) made;
    try {
      made = make(context, values);
    } catch (...) {
      util::rethrow_as_component_failure(who);
    }
    if (!made) throw util::ComponentFailure(who + " made nothing");
    return wrap(std::move(made), who);
  };
}

#undef PLANTSIM_GUARDED

}  // namespace

controller::LocalControllerEntry guarded(controller::LocalControllerEntry e,
                                         const std::string& origin) {
  // Not wrapped: the path follower catches around its calls (local_controller.h).
  guard_factory(e, "local controller \"" + e.name + "\" of " + origin,
                [](std::unique_ptr<controller::LocalController> made, const std::string& who) {
                  made->set_plugin_origin(who);
                  return made;
                });
  return e;
}

robot::EstimatorEntry guarded(robot::EstimatorEntry e, const std::string& origin) {
  guard_factory(e, "estimator \"" + e.name + "\" of " + origin,
                [](std::unique_ptr<robot::PoseEstimator> made, const std::string& who) {
                  return std::unique_ptr<robot::PoseEstimator>(
                      std::make_unique<GuardedEstimator>(std::move(made), who));
                });
  return e;
}

}  // namespace plantsim::plugins
