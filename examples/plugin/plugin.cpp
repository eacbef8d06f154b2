// The plugin's entry: its ABI version and the registration of its two components.
#include "dead_reckoning.h"
#include "plugins/plugin_api.h"
#include "stanley_controller.h"

namespace {

void register_components(plantsim::plugins::Registrar& r) {
  r.add_local_controller(example::stanley_entry());
  r.add_estimator(example::dead_reckoning_entry());
}

}  // namespace

PLANTSIM_PLUGIN(register_components)
