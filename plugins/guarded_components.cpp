// The guards: a plugin's factories inside a try; its estimators wrapped, each call inside a try;
// its local controllers marked with their origin (the path follower catches around its calls,
// which costs nothing while nothing throws). Any exception leaves as a ComponentFailure that says
// whose it was.
#include "plugins/guarded_components.h"

#include <exception>
#include <utility>

#include "util/component_failure.h"

namespace plantsim::plugins {

using geom::Vec2;

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

class GuardedDockDetector : public robot::DockDetector {
 public:
  GuardedDockDetector(std::unique_ptr<robot::DockDetector> inner, std::string who)
      : inner_(std::move(inner)), who_(std::move(who)) {}
  std::optional<robot::ChargerDetection> detect(const robot::DockDetectorQuery& q) override {
    PLANTSIM_GUARDED(inner_->detect(q))
  }

 private:
  std::unique_ptr<robot::DockDetector> inner_;
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

/// A plugin's planner, each call inside a try. One whose factory threw stands in as a planner
/// whose every query throws: the failure then ends each episode that asks it, with its reason,
/// as a throwing query would (a batch builds its planners apart from the episodes).
class GuardedPlanner : public planner::Planner {
 public:
  GuardedPlanner(std::unique_ptr<planner::Planner> inner, std::string name, std::string who,
                 std::string factory_failure)
      : inner_(std::move(inner)),
        name_(std::move(name)),
        who_(std::move(who)),
        factory_failure_(std::move(factory_failure)) {}
  std::string name() const override { return name_; }
  planner::PlanResult plan(Vec2 start, Vec2 goal) override{
      PLANTSIM_GUARDED(made().plan(start, goal))} std::vector<std::pair<Vec2, Vec2>> graph_edges()
      const override{PLANTSIM_GUARDED(made().graph_edges())} std::optional<
          planner::PlanResult> plan_around_added(const std::vector<geom::Rect>& added, Vec2 start,
                                                 Vec2 goal) const override {
    PLANTSIM_GUARDED(made().plan_around_added(added, start, goal))
  }

 private:
  planner::Planner& made() const {
    if (!inner_) throw util::ComponentFailure(factory_failure_);
    return *inner_;
  }

  std::unique_ptr<planner::Planner> inner_;
  std::string name_, who_, factory_failure_;
};

#undef PLANTSIM_GUARDED

}  // namespace

robot::DockDetectorEntry guarded(robot::DockDetectorEntry e, const std::string& origin) {
  guard_factory(e, "dock detector \"" + e.name + "\" of " + origin,
                [](std::unique_ptr<robot::DockDetector> made, const std::string& who) {
                  return std::unique_ptr<robot::DockDetector>(
                      std::make_unique<GuardedDockDetector>(std::move(made), who));
                });
  return e;
}

planner::PlannerEntry guarded(planner::PlannerEntry e, const std::string& origin) {
  const std::string who = "planner \"" + e.name + "\" of " + origin;
  auto make = std::move(e.make);
  e.make = [make, who, name = e.name](const planner::PlannerInput& input) {
    std::unique_ptr<planner::Planner> made;
    std::string failure;
    try {
      made = make(input);
      if (!made) failure = who + " made nothing";
    } catch (const std::exception& x) {
      failure = who + " threw: " + x.what();
    } catch (...) {
      failure = who + " threw something that is not a std::exception";
    }
    return std::unique_ptr<planner::Planner>(
        std::make_unique<GuardedPlanner>(std::move(made), name, who, failure));
  };
  return e;
}

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
