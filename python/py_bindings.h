// The parts of the Python module, each binding one concept (python/module.cpp calls them).
#pragma once

#include <pybind11/pybind11.h>

namespace plantsim::python {

namespace py = pybind11;

void bind_world(py::module_& m);
void bind_plan(py::module_& m);
void bind_run(py::module_& m);
void bind_batch(py::module_& m);
void bind_tune(py::module_& m);
void bind_nav2(py::module_& m);
void bind_env(py::module_& m);
void bind_plugins(py::module_& m);

}  // namespace plantsim::python
