// Conversions between plantsim's C++ values and Python's: points and poses as numpy arrays,
// JSON documents as Python dicts (through Python's own json module, so a dict passed in is
// read by the same parser as a file), and the module's exception types.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::python {

namespace py = pybind11;

/// N x 2 array of (x, y).
py::array_t<double> points_array(const std::vector<geom::Vec2>& points);
/// [x, y, yaw].
py::array_t<double> pose_array(const geom::Pose2& pose);
/// A pose from any sequence of three numbers; `what` names it in the error.
geom::Pose2 pose_from(const py::handle& value, const std::string& what);

/// JSON text as the equal Python object (dict, list, ...), and back.
py::object from_json_text(const std::string& text);
std::string to_json_text(const py::handle& value);

/// Maps the errors the command line answers with exit 2 (bad input) to plantsim.InputError
/// (a ValueError), and the others to RuntimeError, with the same messages.
void register_exceptions(py::module_& m);

}  // namespace plantsim::python
