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
  /// `threads` in all, the caller among them (1: everything on the caller).
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Runs job(i) for every i in [0, n), spread over the threads; returns when all are done. The
  /// first exception a job throws is rethrown here (the other jobs still run).
  void run(std::size_t n, const std::function<void(std::size_t)>& job);

 private:
  void work(const std::function<void(std::size_t)>& job, std::size_t n);
  void help();
  std::vector<std::thread> helpers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::uint64_t generation_ = 0;
  bool stopping_ = false;
  const std::function<void(std::size_t)>* job_ = nullptr;
  std::size_t n_ = 0;
  std::atomic<std::size_t> next_{0};
  std::atomic<int> pending_{0};                    // helpers yet to finish the run at hand
  std::atomic<std::uint64_t> generation_seen_{0};  // generation_, for the helpers' spin
  std::exception_ptr failure_;
};

}  // namespace plantsim::util
