// A test plugin that loads: "test-thrower", a local controller that creeps along and throws after
// `test-thrower.throw_after_steps` steps (never while negative), and "test-map-refuser", whose
// factory throws for any map with boxes (so never at load, always in an episode).
#include <stdexcept>

#include "plugins/plugin_api.h"

namespace {

using namespace plantsim;

class Thrower : public controller::LocalController {
 public:
  explicit Thrower(long long after) : after_(after) {}
  void set_path(std::vector<geom::Vec2>) override {}
  controller::TrackingCommand step(const controller::LocalQuery&) override {
    if (after_ >= 0 && steps_++ >= after_) throw std::runtime_error("the test controller gave up");
    controller::TrackingCommand c;
    c.twist = {0.05, 0.0};
    return c;
  }

 private:
  long long after_, steps_ = 0;
};

void register_components(plugins::Registrar& r) {
  controller::LocalControllerEntry thrower;
  thrower.name = "test-thrower";
  thrower.summary = "throws after a number of steps";
  thrower.params = {{"test-thrower", "throw_after_steps", util::ParamKind::kWhole, 30, -1, 100000,
                     false, "steps before it throws (-1: never)"}};
  thrower.make = [](const controller::LocalControllerContext&, const util::ParamValues& v) {
    return std::make_unique<Thrower>(v.whole("test-thrower.throw_after_steps"));
  };
  r.add_local_controller(thrower);
  controller::LocalControllerEntry refuser;
  refuser.name = "test-map-refuser";
  refuser.summary = "refuses any map with boxes";
  refuser.make = [](const controller::LocalControllerContext& c,
                    const util::ParamValues&) -> std::unique_ptr<controller::LocalController> {
    if (!c.map_obstacles.empty()) throw std::runtime_error("this map has boxes");
    return std::make_unique<Thrower>(-1);
  };
  r.add_local_controller(refuser);
}

}  // namespace

PLANTSIM_PLUGIN(register_components)
