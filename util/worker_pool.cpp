// Worker threads sharing indexed jobs with the caller (see the header). A job is claimed with
// the run's generation (one atomic word holds both), so a helper that wakes late, after its run
// is over, claims nothing of a later run; run() returns once every job of its run has
// completed, whoever ran it, and never waits for a helper that took none: on a busy machine a
// helper the kernel has not scheduled used to hold every run up until it woke to find nothing
// left (VectorEnv(8) made 19,102 steps/s on two threads against 73,336 on one). Waits spin
// briefly before they sleep: runs come every few hundred microseconds, and waking a sleeping
// thread took longer than the work saved (two threads stepped 8 environments slower than one).
#include "util/worker_pool.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
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

std::size_t WorkerPool::claim(std::uint32_t generation, std::size_t n) {
  std::uint64_t state = claim_.load(std::memory_order_acquire);
  for (;;) {
    const std::uint64_t next = state & 0xffffffffULL;
    if ((state >> 32) != generation || next >= n) return n;
    if (claim_.compare_exchange_weak(state, state + 1, std::memory_order_acq_rel)) return next;
  }
}

void WorkerPool::work(const std::function<void(std::size_t)>& job, std::size_t n,
                      std::uint32_t generation) {
  for (std::size_t i; (i = claim(generation, n)) < n;) {
    try {
      job(i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!failure_) failure_ = std::current_exception();
    }
    if (completed_.fetch_add(1, std::memory_order_acq_rel) + 1 == n) {
      { std::lock_guard<std::mutex> lock(mutex_); }  // run() may be about to sleep on done_
      done_.notify_all();
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
    // The run may be over already (the caller did every job): then nothing is claimed, and the
    // job, which belongs to the caller's frame, is never called.
    work(*job, n, static_cast<std::uint32_t>(seen));
  }
}

void WorkerPool::run(std::size_t n, const std::function<void(std::size_t)>& job) {
  if (n == 0) return;
  if (n > 0xffffffffULL) throw std::length_error("WorkerPool::run: more than 2^32 jobs");
  std::uint32_t generation = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = &job;
    n_ = n;
    failure_ = nullptr;
    completed_.store(0, std::memory_order_relaxed);
    ++generation_;
    generation = static_cast<std::uint32_t>(generation_);
    claim_.store(std::uint64_t{generation} << 32, std::memory_order_release);
    generation_seen_.store(generation_, std::memory_order_release);
  }
  wake_.notify_all();
  work(job, n, generation);
  if (!spin_until([&] { return completed_.load(std::memory_order_acquire) == n; })) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return completed_.load(std::memory_order_acquire) == n; });
  }
  std::exception_ptr failure;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    failure = failure_;
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace plantsim::util
