// Worker threads sharing indexed jobs with the caller (see the header). Every helper takes part
// in every run, if only to find nothing left: run() returns once all have, so none still holds
// a job of an earlier run when the next begins. Waits spin briefly before they sleep: runs come
// every few hundred microseconds, and waking a sleeping thread took longer than the work saved
// (two threads stepped 8 environments slower than one).
#include "util/worker_pool.h"

#include <algorithm>
#include <chrono>
#include <system_error>

namespace plantsim::util {
namespace {

/// Polls `ready` for up to about 200 us; true when it became true.
template <class Ready>
bool spin_until(Ready ready) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(200);
  for (int k = 0;; ++k) {
    if (ready()) return true;
    if ((k & 63) == 63 && std::chrono::steady_clock::now() > until) return false;
  }
}

}  // namespace

WorkerPool::WorkerPool(int threads, const ThreadStarter& start) {
  const int wanted = std::min(threads, max_threads());
  for (int t = 1; t < wanted; ++t) {
    try {
      helpers_.push_back(start ? start([this] { help(); }) : std::thread([this] { help(); }));
    } catch (const std::system_error&) {
      // No more threads to be had (RLIMIT_NPROC, memory for a stack): run with those started.
      // Throwing here instead would destroy the started, joinable helpers: std::terminate.
      break;
    }
  }
}

int WorkerPool::max_threads() {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return static_cast<int>(std::min(4u * cores, 1024u));
}

int WorkerPool::threads_for(int requested, std::size_t jobs) {
  const int asked = requested > 0
                        ? requested
                        : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const auto most = static_cast<int>(std::min<std::size_t>(
      std::max<std::size_t>(jobs, 1), static_cast<std::size_t>(max_threads())));
  return std::clamp(asked, 1, most);
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : helpers_) t.join();
}

void WorkerPool::work(const std::function<void(std::size_t)>& job, std::size_t n) {
  for (std::size_t i; (i = next_.fetch_add(1)) < n;) {
    try {
      job(i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!failure_) failure_ = std::current_exception();
    }
  }
}

void WorkerPool::help() {
  std::uint64_t seen = 0;
  for (;;) {
    spin_until([&] { return generation_seen_.load(std::memory_order_acquire) != seen; });
    const std::function<void(std::size_t)>* job = nullptr;
    std::size_t n = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      job = job_, n = n_;
    }
    work(*job, n);
    pending_.fetch_sub(1, std::memory_order_acq_rel);
    {
      std::lock_guard<std::mutex> lock(mutex_);  // run() may be about to sleep on done_
    }
    done_.notify_all();
  }
}

void WorkerPool::run(std::size_t n, const std::function<void(std::size_t)>& job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = &job;
    n_ = n;
    next_ = 0;
    failure_ = nullptr;
    pending_ = static_cast<int>(helpers_.size());
    ++generation_;
    generation_seen_.store(generation_, std::memory_order_release);
  }
  wake_.notify_all();
  work(job, n);
  if (!spin_until([&] { return pending_.load(std::memory_order_acquire) == 0; })) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return pending_.load(std::memory_order_acquire) == 0; });
  }
  std::exception_ptr failure;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    failure = failure_;
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace plantsim::util
