// Pure pursuit behind the local controller interface.
#include "controller/pure_pursuit_controller.h"

#include "controller/controller_param_rows.h"
#include "controller/pure_pursuit.h"

namespace plantsim::controller {

namespace {

class PurePursuitController : public LocalController {
 public:
  explicit PurePursuitController(PurePursuitParams p) : tracker_(p, {}) {}
  void set_path(std::vector<geom::Vec2> path) override {
    tracker_ = PurePursuit(tracker_.params(), std::move(path));
  }
  TrackingCommand step(const LocalQuery& q) override { return tracker_.step(q.pose, q.speed_mps); }

 private:
  PurePursuit tracker_;
};

}  // namespace

std::unique_ptr<LocalController> make_pure_pursuit(const PurePursuitParams& p) {
  return std::make_unique<PurePursuitController>(p);
}

LocalControllerEntry pure_pursuit_entry() {
  LocalControllerEntry e;
  e.name = "pure-pursuit";
  e.summary =
      "regulated pure pursuit (Nav2's RPP): carrot on the plan, slowed on curves and "
      "near the goal, turns in place at sharp corners";
  e.params = util::specs_of(pure_pursuit_param_rows());
  e.capabilities = {"stops-at-corners"};
  e.make = [](const LocalControllerContext&, const util::ParamValues& v) {
    return make_pure_pursuit(util::struct_of(pure_pursuit_param_rows(), v));
  };
  return e;
}

}  // namespace plantsim::controller
