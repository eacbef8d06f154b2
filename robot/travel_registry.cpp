// The travel modes by name (see the header): the built-ins' entries.
#include "robot/travel_registry.h"

namespace plantsim::robot {

namespace {

TravelEntry path_travel() {
  TravelEntry e;
  e.name = "path";
  e.summary =
      "follow the planner's path with the local controller, then dock (a moving "
      "target: chase it along plans made again every period)";
  e.capabilities = {travel_capability::kNeedsAPlan};
  e.make = [](const TravelContext& x, const util::ParamValues&) {
    return x.map->target ? make_pursuit_travel(*x.map, x.planner_name, *x.settings, x.first_path)
                         : make_path_travel(*x.map, x.planner_name, *x.settings, x.first_path);
  };
  return e;
}

TravelEntry field_travel() {
  TravelEntry e;
  e.name = "potential-field";
  e.summary =
      "seed 001: potential field with wall following, then dock (the plan is only the "
      "reference); parameters in `field`";
  e.capabilities = {travel_capability::kStartsAtMotorLimit};
  e.make = [](const TravelContext& x, const util::ParamValues&) {
    return make_field_travel(*x.map, x.planner_name, *x.settings, x.map->target.has_value(),
                             x.map->robot.radius_m);
  };
  return e;
}

}  // namespace

TravelRegistry& travel_modes() {
  static TravelRegistry* registry = [] {
    auto* r = new TravelRegistry("travel mode");
    r->add(path_travel(), "built-in");
    r->add(field_travel(), "built-in");
    return r;
  }();
  return *registry;
}

}  // namespace plantsim::robot
