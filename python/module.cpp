// The extension plantsim._plantsim; python/plantsim/__init__.py re-exports it with the
// pure-Python conveniences. Every call sees only what the command line would: a controller
// given to run() or batch() is called with the robot's perception, never the simulator's truth.
#include <pybind11/numpy.h>

#include "python/py_bindings.h"
#include "python/py_convert.h"

PYBIND11_MODULE(_plantsim, m) {
  using namespace plantsim::python;
  m.doc() = "plantsim: physics testbed for a wheeled robot driving to its charger";
  // numpy's C API is bound here, once, under the import lock: bound lazily on a first call, two
  // threads that released the GIL while it was being bound deadlocked every time.
  (void)py::array_t<double>(0);
  register_exceptions(m);
  bind_world(m);
  bind_plan(m);
  bind_run(m);
  bind_batch(m);
  bind_tune(m);
  bind_nav2(m);
  bind_env(m);
  bind_plugins(m);
}
