// Timing the local controller's calls (see the header).
#include "episode/controller_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace plantsim::episode {
namespace {

/// A controller whose step calls are timed; a plugin's keeps its origin, so that the path
/// follower still names it when a call throws (the exception passes through untouched).
class TimedController final : public controller::LocalController {
 public:
  TimedController(std::unique_ptr<controller::LocalController> inner, ControllerClock& clock)
      : inner_(std::move(inner)),
        clock_(clock),
        sketcher_(dynamic_cast<const controller::SketchesTrajectories*>(inner_.get())) {
    set_plugin_origin(inner_->plugin_origin());
  }
  void set_path(std::vector<geom::Vec2> path) override { inner_->set_path(std::move(path)); }
  controller::TrackingCommand step(const controller::LocalQuery& q) override {
    const auto began = std::chrono::steady_clock::now();
    controller::TrackingCommand out = inner_->step(q);
    clock_.add(std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count());
    if (sketcher_ && clock_.sketch_wanted())
      clock_.keep_sketch(sketcher_->last_trajectories(kSketchSamples, kSketchPoints));
    return out;
  }

 private:
  std::unique_ptr<controller::LocalController> inner_;
  ControllerClock& clock_;
  const controller::SketchesTrajectories* sketcher_;  ///< inner_ when it samples, else null
};

}  // namespace

double ControllerClock::quantile_ms(double q) const {
  if (seconds_.empty()) return NAN;
  std::vector<double> s = seconds_;
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(s.size())));
  const std::size_t k = std::clamp<std::size_t>(rank, 1, s.size()) - 1;
  std::nth_element(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(k), s.end());
  return 1000.0 * s[k];
}

controller::LocalControllerEntry timed_entry(const controller::LocalControllerEntry& entry,
                                             ControllerClock& clock) {
  controller::LocalControllerEntry timed = entry;
  timed.make =
      [make = entry.make, &clock](
          const controller::LocalControllerContext& context,
          const util::ParamValues& values) -> std::unique_ptr<controller::LocalController> {
    std::unique_ptr<controller::LocalController> made = make(context, values);
    if (!made) return made;  // the travel reports an entry that made nothing
    return std::make_unique<TimedController>(std::move(made), clock);
  };
  return timed;
}

}  // namespace plantsim::episode
