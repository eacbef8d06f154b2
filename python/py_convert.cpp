// Numpy arrays, JSON and exceptions between C++ and Python.
#include "python/py_convert.h"

#include <cerrno>
#include <cmath>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <system_error>

#include "util/data_dir.h"
#include "worlds/world_error.h"
#include "worlds/world_limits.h"

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

namespace {

std::string argument_type_name(const py::handle& value) {
  return py::str(py::type::of(value).attr("__name__")).cast<std::string>();
}

std::string short_repr(const py::handle& value) {
  std::string r = py::repr(value).cast<std::string>();
  if (r.size() > 80) r = r.substr(0, 77) + "...";
  return r;
}

/// A Python int (or anything with __index__, not bool) as a Python int; TypeError otherwise.
py::int_ whole_number(const py::handle& value, const std::string& what) {
  if (PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr()))
    throw py::type_error(what + " must be a whole number (int), got " + argument_type_name(value) +
                         " " + short_repr(value));
  return py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
}

}  // namespace

geom::Pose2 pose_from(const py::handle& value, const std::string& what) {
  std::vector<double> v;
  try {
    if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value)) throw py::cast_error();
    v = value.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
    throw py::type_error(what +
                         " expects (x, y, yaw) in metres, metres, radians: three numbers, got " +
                         argument_type_name(value) + " " + short_repr(value));
  }
  if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    throw std::invalid_argument(what + " expects three finite numbers (x, y, yaw), got " +
                                short_repr(value));
  // The limits world files have (worlds/world_limits.h): a yaw of 1e39 is no heading.
  if (std::fabs(v[0]) > worlds::kMaxCoordinate_m || std::fabs(v[1]) > worlds::kMaxCoordinate_m)
    throw std::invalid_argument(what + ": x and y must be within +-1e7 m, got " +
                                short_repr(value));
  if (std::fabs(v[2]) > worlds::kMaxYaw_rad)
    throw std::invalid_argument(what + ": yaw must be from -100 to 100 rad, got " +
                                short_repr(value));
  return {v[0], v[1], v[2]};
}

std::int64_t whole_from(const py::handle& value, const std::string& what, std::int64_t lo,
                        std::int64_t hi) {
  const py::int_ i = whole_number(value, what);
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
  if (overflow != 0 || v < lo || v > hi)
    throw std::invalid_argument(what + " must be from " + std::to_string(lo) + " to " +
                                std::to_string(hi) + ", got " + short_repr(value));
  return v;
}

std::uint64_t seed_from(const py::handle& value, const std::string& what) {
  const py::int_ i = whole_number(value, what);
  int overflow = 0;
  const long long small = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
  if (overflow == 0 && small >= 0) return static_cast<std::uint64_t>(small);
  if (overflow > 0) {
    const unsigned long long big = PyLong_AsUnsignedLongLong(i.ptr());
    if (!PyErr_Occurred()) return big;
    PyErr_Clear();
  }
  throw std::invalid_argument(what + " must be from 0 to 2**64 - 1, got " + short_repr(value));
}

std::string path_from(const py::handle& value, const std::string& what) {
  if (!py::isinstance<py::str>(value) && !py::hasattr(value, "__fspath__"))
    throw py::type_error(what + " must be a path (str or os.PathLike), got " +
                         argument_type_name(value));
  const py::object text = py::module_::import("os").attr("fspath")(value);
  if (!py::isinstance<py::str>(text))
    throw py::type_error(what + " must be a text path, got " + argument_type_name(text));
  return text.cast<std::string>();
}

std::string file_from(const py::handle& value, const std::string& what) {
  const std::string written = path_from(value, what);
  std::error_code ec;
  const std::string resolved = util::resolve_input_path(written, "");
  if (!std::filesystem::exists(resolved, ec))
    throw MissingFile(what + ": no such file: '" + written + "'", resolved);
  return written;
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

namespace {

py::object& input_error_type() {
  static py::object* type = nullptr;  // the module's; kept for the process (never released)
  if (!type) type = new py::object(py::module_::import("plantsim._plantsim").attr("InputError"));
  return *type;
}

void set_input_error(const std::string& message, const std::string* file,
                     const std::string* field) {
  py::object error = input_error_type()(message);
  if (file) error.attr("file") = *file;
  if (field && !field->empty()) error.attr("field") = *field;
  PyErr_SetObject(input_error_type().ptr(), error.ptr());
}

/// plantsim's own exceptions; false (nothing set) for the others.
bool set_plantsim_error(const std::exception_ptr& p) {
  try {
    std::rethrow_exception(p);
  } catch (const MissingFile& e) {
    const py::object error =
        py::reinterpret_borrow<py::object>(PyExc_FileNotFoundError)(ENOENT, e.what(), e.path);
    PyErr_SetObject(PyExc_FileNotFoundError, error.ptr());
  } catch (const worlds::WorldError& e) {  // names the file and the field, as the CLI prints it
    if (!std::filesystem::exists(e.file()) && e.field().empty() &&
        std::string(e.what()).find("no such file") != std::string::npos) {
      const py::object error =
          py::reinterpret_borrow<py::object>(PyExc_FileNotFoundError)(ENOENT, e.what(), e.file());
      PyErr_SetObject(PyExc_FileNotFoundError, error.ptr());
    } else {
      set_input_error(e.what(), &e.file(), &e.field());
    }
  } catch (const std::invalid_argument& e) {
    set_input_error(e.what(), nullptr, nullptr);
  } catch (...) {
    return false;
  }
  return true;
}

}  // namespace

void register_exceptions(py::module_& m) {
  static py::exception<std::invalid_argument> input_error(m, "InputError", PyExc_ValueError);
  input_error.attr("__doc__") =
      "Bad input: a value out of range, a file's field (.file and .field name them), an action.";
  input_error.attr("file") = py::none();  // class defaults: set on instances when known
  input_error.attr("field") = py::none();
  py::register_exception_translator([](std::exception_ptr p) {
    if (p && !set_plantsim_error(p)) std::rethrow_exception(p);  // pybind11's own map then
  });
}

void set_python_error(std::exception_ptr e) {
  if (set_plantsim_error(e)) return;
  try {
    std::rethrow_exception(e);
  } catch (py::error_already_set& python) {
    python.restore();
  } catch (const py::builtin_exception& builtin) {
    builtin.set_error();
  } catch (const std::bad_alloc&) {
    PyErr_SetString(PyExc_MemoryError, "out of memory");
  } catch (const std::exception& other) {
    PyErr_SetString(PyExc_RuntimeError, other.what());
  } catch (...) {
    PyErr_SetString(PyExc_RuntimeError, "unknown C++ exception");
  }
}

}  // namespace plantsim::python
