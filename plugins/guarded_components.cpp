// The guards: each call of a plugin's component inside a try, any exception rethrown as a
// ComponentFailure that says whose it was.
#include "plugins/guarded_components.h"

#include <exception>
#include <utility>

#include "util/component_failure.h"

namespace plantsim::plugins {

namespace {

/// Runs `call`; anything it throws becomes a ComponentFailure naming `who`.
template <typename Call>
auto guard(const std::string& who, Call&& call) -> decltype(call()) {
  try {
    return call();
  } catch (const util::ComponentFailure&) {
    throw;
  } catch (const std::exception& e) {
    throw util::ComponentFailure(who + " threw: " + e.what());
  } catch (...) {
    throw util::ComponentFailure(who + " threw something that is not a std::exception");
  }
}

class GuardedLocalController : public controller::LocalController {
 public:
  GuardedLocalController(std::unique_ptr<controller::LocalController> inner, std::string who)
      : inner_(std::move(inner)), who_(std::move(who)) {}
  void set_path(std::vector<geom::Vec2> path) override {
    guard(who_, [&] { inner_->set_path(std::move(path)); });
  }
  controller::TrackingCommand step(const controller::LocalQuery& q) override {
    return guard(who_, [&] { return inner_->step(q); });
  }

 private:
  std::unique_ptr<controller::LocalController> inner_;
  std::string who_;
};

class GuardedEstimator : public robot::PoseEstimator {
 public:
  GuardedEstimator(std::unique_ptr<robot::PoseEstimator> inner, std::string who)
      : inner_(std::move(inner)), who_(std::move(who)) {}
  void predict(double d, double w, double dt) override {
    guard(who_, [&] { inner_->predict(d, w, dt); });
  }
  void standstill(double w, double dt) override {
    guard(who_, [&] { inner_->standstill(w, dt); });
  }
  void observe(const robot::LidarScan& scan) override {
    guard(who_, [&] { inner_->observe(scan); });
  }
  void widen(double p, double y) override {
    guard(who_, [&] { inner_->widen(p, y); });
  }
  geom::Pose2 pose() const override {
    return guard(who_, [&] { return inner_->pose(); });
  }
  Eigen::Matrix3d pose_covariance() const override {
    return guard(who_, [&] { return inner_->pose_covariance(); });
  }
  double position_sigma_m() const override {
    return guard(who_, [&] { return inner_->position_sigma_m(); });
  }
  double yaw_sigma_rad() const override {
    return guard(who_, [&] { return inner_->yaw_sigma_rad(); });
  }
  double gyro_bias_radps() const override {
    return guard(who_, [&] { return inner_->gyro_bias_radps(); });
  }
  double range_sigma_m() const override {
    return guard(who_, [&] { return inner_->range_sigma_m(); });
  }
  robot::LocalizationHealth health() const override {
    return guard(who_, [&] { return inner_->health(); });
  }
  int failed_matches() const override {
    return guard(who_, [&] { return inner_->failed_matches(); });
  }
  bool lost_in_view() const override {
    return guard(who_, [&] { return inner_->lost_in_view(); });
  }
  int relocalizations() const override {
    return guard(who_, [&] { return inner_->relocalizations(); });
  }

 private:
  std::unique_ptr<robot::PoseEstimator> inner_;
  std::string who_;
};

/// Guards the factory, and what it makes.
template <typename Entry, typename Guarded>
void guard_factory(Entry& e, const std::string& who) {
  auto make = std::move(e.make);
  e.make = [make, who](const auto& context, const util::ParamValues& values) {
    auto made = guard(who, [&] { return make(context, values); });
    if (!made) throw util::ComponentFailure(who + " made nothing");
    using Interface = typename decltype(made)::element_type;
    return std::unique_ptr<Interface>(std::make_unique<Guarded>(std::move(made), who));
  };
}

}  // namespace

controller::LocalControllerEntry guarded(controller::LocalControllerEntry e,
                                         const std::string& origin) {
  guard_factory<controller::LocalControllerEntry, GuardedLocalController>(
      e, "local controller \"" + e.name + "\" of " + origin);
  return e;
}

robot::EstimatorEntry guarded(robot::EstimatorEntry e, const std::string& origin) {
  guard_factory<robot::EstimatorEntry, GuardedEstimator>(
      e, "estimator \"" + e.name + "\" of " + origin);
  return e;
}

}  // namespace plantsim::plugins
