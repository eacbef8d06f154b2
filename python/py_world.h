// plantsim.World and plantsim.load_world: a plant as Python sees it (read-only arrays of its
// rectangles and poses), loaded from any format the command line reads.
#pragma once

#include <memory>

#include "python/py_convert.h"
#include "worlds/world.h"

namespace plantsim::python {

/// What Python holds: one loaded world, shared by the plans and runs made on it.
struct PyWorld {
  std::shared_ptr<const worlds::World> world;
};

/// A World argument given as a World or as a path to load.
PyWorld world_argument(const py::handle& value);

void bind_world(py::module_& m);

}  // namespace plantsim::python
