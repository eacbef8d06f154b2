// The worker thread and the signal checks of run_interruptibly; the partial-result exceptions.
#include "python/py_interrupt.h"

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <utility>

#include "python/py_convert.h"

namespace plantsim::python {

Interruptible run_interruptibly(const std::function<void()>& work, std::atomic<bool>& stop) {
  Interruptible out;
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  {
    py::gil_scoped_release free_python;
    const auto body = [&] {
      try {
        work();
      } catch (...) {
        out.failure = std::current_exception();
      }
      std::lock_guard lock(m);
      done = true;
      cv.notify_one();
    };
    std::thread worker;
    try {
      worker = std::thread(body);
    } catch (const std::system_error&) {
      body();  // no thread to be had (a thread or memory limit): run here, not interruptibly
    }
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
    if (worker.joinable()) worker.join();
  }
  return out;
}

CallGuard::Held::~Held() {
  g_.owner_.store(std::thread::id{});
  g_.mutex_.unlock();
}

CallGuard::Held CallGuard::enter(const char* what) {
  if (owner_.load() == std::this_thread::get_id())
    throw std::runtime_error(std::string(what) +
                             " is in a call on this thread already (a reward function or callback "
                             "that calls it back): its calls cannot nest");
  if (!mutex_.try_lock()) {
    for (;;) {  // another thread's call: wait without the GIL, which that call needs back
      bool got = false;
      {
        py::gil_scoped_release free_python;
        got = mutex_.try_lock_for(std::chrono::milliseconds(50));
      }
      if (got) break;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
  }
  owner_.store(std::this_thread::get_id());
  return Held(*this);
}

Background::~Background() {
  if (!thread_.joinable()) return;
  if (PyGILState_Check()) {
    py::gil_scoped_release free_python;
    thread_.join();
  } else {
    thread_.join();
  }
}

void Background::wait_interruptibly() {
  for (;;) {
    {
      py::gil_scoped_release free_python;
      std::unique_lock lock(mutex_);
      if (done_cv_.wait_for(lock, std::chrono::milliseconds(50), [&] { return done_; })) return;
    }
    if (PyErr_CheckSignals() != 0) {
      stop_ = true;
      throw py::error_already_set();  // the KeyboardInterrupt; the work runs on to its end
    }
  }
}

bool Background::settle() {
  if (!thread_.joinable()) return false;
  wait_interruptibly();
  thread_.join();
  failure_ = nullptr;  // the outcome of an interrupted call: nobody waits for it
  return true;
}

void Background::run(std::function<void()> work) {
  settle();
  stop_ = false;
  {
    std::lock_guard lock(mutex_);
    done_ = false;
    failure_ = nullptr;
  }
  auto body = [this, work = std::move(work)] {
    std::exception_ptr failure;
    try {
      work();
    } catch (...) {
      failure = std::current_exception();
    }
    std::lock_guard lock(mutex_);
    failure_ = failure;
    done_ = true;
    done_cv_.notify_all();
  };
  try {
    thread_ = std::thread(body);
  } catch (const std::system_error&) {  // no thread to be had: on the caller, uninterruptible
    py::gil_scoped_release free_python;
    body();
  }
  wait_interruptibly();
  if (thread_.joinable()) thread_.join();
  std::exception_ptr failure;
  std::swap(failure, failure_);
  if (failure) std::rethrow_exception(failure);
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
  set_python_error(e);  // the module's one map (py_convert.h)
  return py::error_already_set();
}

}  // namespace plantsim::python
