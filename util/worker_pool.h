// A fixed set of worker threads that run one indexed job at a time with the calling thread
// (VectorEnv's step: a few hundred microseconds of work per call, where starting threads at each
// call cost more than it saved).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace plantsim::util {

class WorkerPool {
 public:
  /// Starts one helper thread running `body` (std::thread by default; tests inject failures).
  using ThreadStarter = std::function<std::thread(std::function<void()>)>;

  /// `threads` in all, the caller among them (1: everything on the caller), at most
  /// max_threads(). A helper that cannot be started (std::thread throws std::system_error under
  /// a thread or memory limit) is left out: the pool runs with those that started, down to the
  /// caller alone, instead of aborting.
  explicit WorkerPool(int threads, const ThreadStarter& start = {});
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Runs job(i) for every i in [0, n), spread over the threads; returns when all are done. The
  /// first exception a job throws is rethrown here (the other jobs still run).
  void run(std::size_t n, const std::function<void(std::size_t)>& job);

  /// The threads the pool runs on, the caller included (fewer than asked when some failed).
  int threads() const { return static_cast<int>(helpers_.size()) + 1; }

  /// The most threads a pool takes: 4 per core. Every helper wakes for every run, so helpers
  /// beyond the cores only add switches (400 on 2 cores spent each run on 400 wake-ups and
  /// spins).
  static int max_threads();
  /// The threads for `jobs` jobs per run when `requested` are asked (0 or less: one per core),
  /// from 1 to the smaller of `jobs` and max_threads().
  static int threads_for(int requested, std::size_t jobs);

 private:
  /// The next job of run `generation` to take, or n when none is left or the run is another.
  std::size_t claim(std::uint32_t generation, std::size_t n);
  void work(const std::function<void(std::size_t)>& job, std::size_t n, std::uint32_t generation);
  void help();
  std::vector<std::thread> helpers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::uint64_t generation_ = 0;
  bool stopping_ = false;
  const std::function<void(std::size_t)>* job_ = nullptr;
  std::size_t n_ = 0;
  std::atomic<std::uint64_t> claim_{0};    // the run's generation (high half), next job (low)
  std::atomic<std::size_t> completed_{0};  // jobs of the run at hand done
  std::atomic<std::uint64_t> generation_seen_{0};  // generation_, for the helpers' spin
  std::exception_ptr failure_;
};

}  // namespace plantsim::util
