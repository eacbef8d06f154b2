// Conversions between plantsim's C++ values and Python's: points and poses as numpy arrays,
// JSON documents as Python dicts (through Python's own json module, so a dict passed in is
// read by the same parser as a file), and the module's exception types.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::python {

namespace py = pybind11;

/// N x 2 array of (x, y).
py::array_t<double> points_array(const std::vector<geom::Vec2>& points);
/// [x, y, yaw].
py::array_t<double> pose_array(const geom::Pose2& pose);
/// A pose from any sequence of three numbers; `what` names it in the error. Not a sequence of
/// numbers: TypeError; not three, not finite, beyond the world files' limits (|x|, |y| <= 1e7 m,
/// |yaw| <= 100 rad, worlds/world_limits.h): InputError.
geom::Pose2 pose_from(const py::handle& value, const std::string& what);

/// A seed: a Python int from 0 to 2**64 - 1 (TypeError for another type, InputError beyond).
std::uint64_t seed_from(const py::handle& value, const std::string& what);
/// A whole number from `lo` to `hi` (TypeError for another type, InputError beyond).
std::int64_t whole_from(const py::handle& value, const std::string& what, std::int64_t lo,
                        std::int64_t hi);
/// A file argument (str or os.PathLike) as written; FileNotFoundError when it names no file
/// (after "$data/" is resolved as the loaders resolve it), TypeError for another type.
std::string file_from(const py::handle& value, const std::string& what);
/// A folder argument (str or os.PathLike) as written; TypeError for another type.
std::string path_from(const py::handle& value, const std::string& what);

/// Raised for a missing input file; Python sees FileNotFoundError with .filename.
struct MissingFile : std::runtime_error {
  MissingFile(const std::string& message, std::string file)
      : std::runtime_error(message), path(std::move(file)) {}
  std::string path;
};

/// JSON text as the equal Python object (dict, list, ...), and back.
py::object from_json_text(const std::string& text);
std::string to_json_text(const py::handle& value);

/// The one map from plantsim's C++ exceptions to Python's, registered as the module's
/// translator and used by python_error_of (py_interrupt.h): worlds::WorldError (a file and a
/// field) -> plantsim.InputError with .file and .field; std::invalid_argument (a bad value) ->
/// plantsim.InputError; MissingFile -> FileNotFoundError; py::type_error -> TypeError (pybind11's
/// own); anything else -> RuntimeError, all with the C++ message. InputError is a ValueError.
void register_exceptions(py::module_& m);

/// Sets the Python error for the C++ exception `e` by that map. Call with the GIL held.
void set_python_error(std::exception_ptr e);

}  // namespace plantsim::python
