// A test plugin that loads: "test-thrower", a local controller that creeps along and throws after
// `test-thrower.throw_after_steps` steps (never while negative), and "test-map-refuser", whose
// factory throws for any map with boxes (so never at load, always in an episode); two planners:
// "test-straight", the straight line to the goal bent sideways by its option `detour_m` at the
// middle (whatever is in the way), and "test-planner-thrower", whose every query throws; two dock
// detectors: "test-offset-camera", the camera's sightings moved sideways by its `offset_m`, and
// "test-detector-thrower", which throws at its first sighting.
#include <cmath>
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

class Straight : public planner::Planner {
 public:
  explicit Straight(double detour_m) : detour_m_(detour_m) {}
  std::string name() const override { return "test-straight"; }
  planner::PlanResult plan(geom::Vec2 start, geom::Vec2 goal) override {
    const geom::Vec2 d = goal - start;
    const double n = std::hypot(d.x, d.y);
    const geom::Vec2 side = n > 0 ? geom::Vec2{-d.y / n, d.x / n} : geom::Vec2{0, 0};
    const geom::Vec2 middle = start + d * 0.5 + side * detour_m_;
    planner::PlanResult r;
    r.status = planner::PlanStatus::kOk;
    r.path = detour_m_ > 0 ? std::vector<geom::Vec2>{start, middle, goal}
                           : std::vector<geom::Vec2>{start, goal};
    for (std::size_t i = 1; i < r.path.size(); ++i) {
      const geom::Vec2 s = r.path[i] - r.path[i - 1];
      r.length += std::hypot(s.x, s.y);
    }
    return r;
  }

 private:
  double detour_m_;
};

class PlannerThrower : public planner::Planner {
 public:
  std::string name() const override { return "test-planner-thrower"; }
  planner::PlanResult plan(geom::Vec2, geom::Vec2) override {
    throw std::runtime_error("the test planner found no way");
  }
};

void register_planners(plugins::Registrar& r) {
  planner::PlannerEntry straight;
  straight.name = "test-straight";
  straight.summary = "the straight line, bent sideways at the middle";
  straight.options = {{"detour_m", 0.0, 0.0, 5.0, false, "sideways offset of the middle point"}};
  straight.make = [spec = straight.options[0]](const planner::PlannerInput& in) {
    return std::make_unique<Straight>(in.options.get(spec));
  };
  r.add_planner(straight);
  planner::PlannerEntry thrower;
  thrower.name = "test-planner-thrower";
  thrower.summary = "throws at every query";
  thrower.make = [](const planner::PlannerInput&) { return std::make_unique<PlannerThrower>(); };
  r.add_planner(thrower);
}

class OffsetCamera : public robot::DockDetector {
 public:
  explicit OffsetCamera(double offset_m, bool throws) : offset_m_(offset_m), throws_(throws) {}
  std::optional<robot::ChargerDetection> detect(const robot::DockDetectorQuery& q) override {
    std::optional<robot::ChargerDetection> d = q.readings->charger;
    if (d && throws_) throw std::runtime_error("the test detector is blinded");
    // Sideways in the docked pose's own frame: the robot docks that far to its left.
    if (d) d->dock_in_robot = geom::compose(d->dock_in_robot, geom::Pose2{0.0, offset_m_, 0.0});
    return d;
  }

 private:
  double offset_m_;
  bool throws_;
};

void register_dock_detectors(plugins::Registrar& r) {
  robot::DockDetectorEntry offset;
  offset.name = "test-offset-camera";
  offset.summary = "the camera's sightings moved sideways";
  offset.params = {{"test-offset-camera", "offset_m", util::ParamKind::kReal, 0.0, -0.2, 0.2, false,
                    "sideways shift of every sighting"}};
  offset.make = [](const robot::DockDetectorContext&, const util::ParamValues& v) {
    return std::make_unique<OffsetCamera>(v.real("test-offset-camera.offset_m"), false);
  };
  r.add_dock_detector(offset);
  robot::DockDetectorEntry thrower;
  thrower.name = "test-detector-thrower";
  thrower.summary = "throws at its first sighting";
  thrower.make = [](const robot::DockDetectorContext&, const util::ParamValues&) {
    return std::make_unique<OffsetCamera>(0.0, true);
  };
  r.add_dock_detector(thrower);
}

void register_components(plugins::Registrar& r) {
  register_planners(r);
  register_dock_detectors(r);
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
