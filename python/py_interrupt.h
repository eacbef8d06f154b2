// C++ work run with the GIL released and stoppable by Ctrl-C: the work runs on a worker thread
// while the calling thread checks Python's signals every 50 ms (PyErr_CheckSignals runs the
// handlers only on the main thread, and only while it holds the GIL); a KeyboardInterrupt sets
// the stop flag the work polls (episode::EpisodeSteering::interrupted). Also: a Python object
// held by C++ that any thread may copy, and the exception raised with the partial result.
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "python/py_bindings.h"

namespace plantsim::python {

struct Interruptible {
  std::exception_ptr failure;  ///< what the work threw, if anything
  std::optional<py::error_already_set>
      signal;  ///< a signal handler's exception (KeyboardInterrupt)
};

/// Runs `work` off the GIL; sets `stop` when a signal handler raises. Call with the GIL held.
Interruptible run_interruptibly(const std::function<void()>& work, std::atomic<bool>& stop);

/// One Python object's calls, one at a time (plantsim.Env, VectorEnv: their stepping runs with
/// the GIL released, and two threads stepping one Env at once crashed). A caller waits for the
/// object with the GIL released (so the holder can take the GIL back to build its results: no
/// deadlock), answering Ctrl-C every 50 ms while it waits. A call from the holding thread itself
/// (a reward function that steps its own Env) is refused with RuntimeError, not deadlocked.
class CallGuard {
 public:
  class Held {
   public:
    explicit Held(CallGuard& g) : g_(g) {}
    ~Held();
    Held(const Held&) = delete;
    Held& operator=(const Held&) = delete;

   private:
    CallGuard& g_;
  };
  /// Call with the GIL held; `what` names the object in the errors ("Env").
  [[nodiscard]] Held enter(const char* what);

 private:
  std::timed_mutex mutex_;
  std::atomic<std::thread::id> owner_{};
};

/// Work that may outlast the call that started it (planning a new episode: seconds on a large
/// plant, and no planner can be stopped halfway). It runs on a thread of its own with the GIL
/// released while the caller answers Ctrl-C every 50 ms; on KeyboardInterrupt the call returns
/// at once, `stop` is set (the work skips what it has not begun), and the next run() or
/// settle() waits for the rest first. The destructor waits for it too, so the work may use its
/// owner's members: declare the Background last (destroyed first).
class Background {
 public:
  Background() = default;
  ~Background();
  Background(const Background&) = delete;
  Background& operator=(const Background&) = delete;

  /// Runs `work` (call with the GIL held): returns when it is done, rethrowing what it threw;
  /// raises KeyboardInterrupt (error_already_set) when a signal handler raised, the work left
  /// running. When no thread can be started, runs `work` on the caller (not interruptible).
  void run(std::function<void()> work);
  /// Waits for interrupted work to end (call with the GIL held; a signal raises again). True
  /// when there was such work (its outcome is dropped: the object must be reset).
  bool settle();
  /// Set when the caller was interrupted; the work checks it between its parts.
  bool stopping() const { return stop_.load(std::memory_order_relaxed); }

 private:
  void wait_interruptibly();
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable done_cv_;
  bool done_ = true;
  std::exception_ptr failure_;
  std::atomic<bool> stop_{false};
};

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
