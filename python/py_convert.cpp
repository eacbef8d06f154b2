// Numpy arrays, JSON and exceptions between C++ and Python.
#include "python/py_convert.h"

#include <cmath>
#include <stdexcept>

#include "worlds/world_error.h"

namespace plantsim::python {

py::array_t<double> points_array(const std::vector<geom::Vec2>& points) {
  py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    v(static_cast<py::ssize_t>(i), 0) = points[i].x;
    v(static_cast<py::ssize_t>(i), 1) = points[i].y;
  }
  return a;
}

py::array_t<double> pose_array(const geom::Pose2& pose) {
  py::array_t<double> a(3);
  auto v = a.mutable_unchecked<1>();
  v(0) = pose.x, v(1) = pose.y, v(2) = pose.yaw;
  return a;
}

geom::Pose2 pose_from(const py::handle& value, const std::string& what) {
  std::vector<double> v;
  try {
    v = value.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
    throw std::invalid_argument(what + " expects (x, y, yaw) in metres, metres, radians");
  }
  if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    throw std::invalid_argument(what + " expects three finite numbers (x, y, yaw)");
  return {v[0], v[1], v[2]};
}

py::object from_json_text(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

std::string to_json_text(const py::handle& value) {
  try {
    return py::module_::import("json")
        .attr("dumps")(value, py::arg("allow_nan") = false)
        .cast<std::string>();
  } catch (const py::error_already_set& e) {
    throw std::invalid_argument(std::string("not a JSON document: ") + e.what());
  }
}

void register_exceptions(py::module_& m) {
  static py::exception<std::invalid_argument> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const worlds::WorldError& e) {  // names the file and the field, as the CLI prints it
      PyErr_SetString(input_error.ptr(), e.what());
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(input_error.ptr(), e.what());
    }
  });
}

}  // namespace plantsim::python
