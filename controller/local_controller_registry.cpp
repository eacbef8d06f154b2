// The built-in local controllers, one line each.
#include "controller/local_controller_registry.h"

#include "controller/dwb/dwb_controller.h"
#include "controller/mppi/mppi_controller.h"
#include "controller/pure_pursuit_controller.h"

namespace plantsim::controller {

LocalControllerRegistry& local_controllers() {
  static LocalControllerRegistry* registry = [] {
    auto* r = new LocalControllerRegistry("local controller");  // never destroyed: plugins'
                                                                // entries outlive main
    r->add(pure_pursuit_entry(), "built-in");
    r->add(mppi::mppi_entry(), "built-in");
    r->add(dwb::dwb_entry(), "built-in");
    return r;
  }();
  return *registry;
}

}  // namespace plantsim::controller
