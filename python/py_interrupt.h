// C++ work run with the GIL released and stoppable by Ctrl-C: the work runs on a worker thread
// while the calling thread checks Python's signals every 50 ms (PyErr_CheckSignals runs the
// handlers only on the main thread, and only while it holds the GIL); a KeyboardInterrupt sets
// the stop flag the work polls (episode::EpisodeSteering::interrupted). Also: a Python object
// held by C++ that any thread may copy, and the exception raised with the partial result.
#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <memory>
#include <optional>

#include "python/py_bindings.h"

namespace plantsim::python {

struct Interruptible {
  std::exception_ptr failure;  ///< what the work threw, if anything
  std::optional<py::error_already_set>
      signal;  ///< a signal handler's exception (KeyboardInterrupt)
};

/// Runs `work` off the GIL; sets `stop` when a signal handler raises. Call with the GIL held.
Interruptible run_interruptibly(const std::function<void()>& work, std::atomic<bool>& stop);

/// Keeps the calling thread's Python thread state from construction to destruction (on the same
/// thread), the GIL not held in between: each gil_scoped_acquire meanwhile reuses it. Without it
/// a thread Python did not start creates and deletes a thread state at every acquire, and
/// Python 3.11 maps and unmaps a 16 KiB frame stack for each: a steered episode paid a page
/// fault and a TLB flush per control period (2.2 x a plain episode's cost, not 1.5).
class PythonThreadState {
 public:
  PythonThreadState();
  ~PythonThreadState();
  PythonThreadState(const PythonThreadState&) = delete;
  PythonThreadState& operator=(const PythonThreadState&) = delete;
};

/// A Python object shared by C++ copies on any thread: copying the handle touches no reference
/// count, and the last copy takes the GIL to release the object.
std::shared_ptr<py::object> share_across_threads(py::object o);

/// Raises `error` (restored as the pending Python exception) with `partial` and `time` set as
/// attributes when the exception type allows it. Call with the GIL held.
[[noreturn]] void raise_with_partial(py::error_already_set& error, const py::object& partial,
                                     double time_s);

/// The Python exception plantsim raises for a C++ exception (InputError for bad input,
/// RuntimeError otherwise), as a pending error to add attributes to. Call with the GIL held.
py::error_already_set python_error_of(std::exception_ptr e);

}  // namespace plantsim::python
