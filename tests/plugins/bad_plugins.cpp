// Test plugins that must be refused, one per PLANTSIM_BAD_PLUGIN value: no ABI symbol, another
// ABI version, a name a built-in has, a factory that throws, a symbol nothing defines, a
// parameter whose default lies outside its bounds, a planner whose factory throws.
#include <stdexcept>

#include "plugins/plugin_api.h"

namespace {

using namespace plantsim;

class Still : public controller::LocalController {
 public:
  void set_path(std::vector<geom::Vec2>) override {}
  controller::TrackingCommand step(const controller::LocalQuery&) override { return {}; }
};

controller::LocalControllerEntry still(const std::string& name) {
  controller::LocalControllerEntry e;
  e.name = name;
  e.make = [](const controller::LocalControllerContext&, const util::ParamValues&) {
    return std::make_unique<Still>();
  };
  return e;
}

}  // namespace

#if PLANTSIM_BAD_PLUGIN == 1  // no ABI symbol
extern "C" __attribute__((visibility("default"))) void plantsim_plugin_register(
    plugins::Registrar& r) {
  r.add_local_controller(still("test-no-abi"));
}
#elif PLANTSIM_BAD_PLUGIN == 2  // another ABI version
extern "C" __attribute__((visibility("default"))) int plantsim_plugin_abi_version() {
  return PLANTSIM_PLUGIN_ABI_VERSION + 1;
}
extern "C" __attribute__((visibility("default"))) void plantsim_plugin_register(
    plugins::Registrar& r) {
  r.add_local_controller(still("test-wrong-abi"));
}
#elif PLANTSIM_BAD_PLUGIN == 3  // a built-in's name
namespace {
void register_components(plugins::Registrar& r) { r.add_local_controller(still("mppi")); }
}  // namespace
PLANTSIM_PLUGIN(register_components)
#elif PLANTSIM_BAD_PLUGIN == 4  // a factory that throws
namespace {
void register_components(plugins::Registrar& r) {
  controller::LocalControllerEntry e = still("test-factory-throws");
  e.make = [](const controller::LocalControllerContext&,
              const util::ParamValues&) -> std::unique_ptr<controller::LocalController> {
    throw std::runtime_error("cannot be built");
  };
  r.add_local_controller(e);
}
}  // namespace
PLANTSIM_PLUGIN(register_components)
#elif PLANTSIM_BAD_PLUGIN == 5  // a symbol nothing defines
extern "C" int plantsim_test_symbol_nobody_defines();
namespace {
void register_components(plugins::Registrar& r) {
  if (plantsim_test_symbol_nobody_defines() > 0) r.add_local_controller(still("test-unresolved"));
}
}  // namespace
PLANTSIM_PLUGIN(register_components)
#elif PLANTSIM_BAD_PLUGIN == 6  // a default outside its bounds
namespace {
void register_components(plugins::Registrar& r) {
  controller::LocalControllerEntry e = still("test-bad-bounds");
  e.params = {{"test-bad-bounds", "gain", util::ParamKind::kReal, 5.0, 0.0, 1.0, false, ""}};
  r.add_local_controller(e);
}
}  // namespace
PLANTSIM_PLUGIN(register_components)
#elif PLANTSIM_BAD_PLUGIN == 7  // a planner whose factory throws
namespace {
void register_components(plugins::Registrar& r) {
  planner::PlannerEntry e;
  e.name = "test-planner-factory-throws";
  e.make = [](const planner::PlannerInput&) -> std::unique_ptr<planner::Planner> {
    throw std::runtime_error("no planner today");
  };
  r.add_planner(e);
}
}  // namespace
PLANTSIM_PLUGIN(register_components)
#endif
