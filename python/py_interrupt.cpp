// The worker thread and the signal checks of run_interruptibly; the partial-result exceptions.
#include "python/py_interrupt.h"

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace plantsim::python {

Interruptible run_interruptibly(const std::function<void()>& work, std::atomic<bool>& stop) {
  Interruptible out;
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  {
    py::gil_scoped_release free_python;
    std::thread worker([&] {
      try {
        work();
      } catch (...) {
        out.failure = std::current_exception();
      }
      std::lock_guard lock(m);
      done = true;
      cv.notify_one();
    });
    std::unique_lock lock(m);
    while (!done) {
      if (cv.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; })) break;
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        if (!out.signal && PyErr_CheckSignals() != 0) {
          out.signal.emplace();  // fetches the pending KeyboardInterrupt
          stop = true;
        }
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  return out;
}

PythonThreadState::PythonThreadState() {
  py::gil_scoped_acquire gil;
  gil.inc_ref();  // one more holder than the scope: the state outlives it
}

PythonThreadState::~PythonThreadState() {
  py::gil_scoped_acquire gil;
  gil.dec_ref();  // the scope's own release then deletes the state (the thread's last holder)
}

std::shared_ptr<py::object> share_across_threads(py::object o) {
  return std::shared_ptr<py::object>(new py::object(std::move(o)), [](py::object* p) {
    py::gil_scoped_acquire gil;
    delete p;
  });
}

void raise_with_partial(py::error_already_set& error, const py::object& partial, double time_s) {
  try {
    error.value().attr("partial") = partial;
    error.value().attr("time") = time_s;
  } catch (const py::error_already_set&) {
    // An exception type without a __dict__ (slots): raised as it is.
  }
  error.restore();
  throw py::error_already_set();
}

py::error_already_set python_error_of(std::exception_ptr e) {
  try {
    std::rethrow_exception(e);
  } catch (const py::error_already_set& python) {
    return python;
  } catch (const std::invalid_argument& bad) {
    PyErr_SetString(py::module_::import("plantsim._plantsim").attr("InputError").ptr(), bad.what());
  } catch (const std::exception& other) {
    PyErr_SetString(PyExc_RuntimeError, other.what());
  } catch (...) {
    PyErr_SetString(PyExc_RuntimeError, "unknown C++ exception");
  }
  return py::error_already_set();
}

}  // namespace plantsim::python
