// The batch's progress bar on stderr: episodes done, rate and time left; on a terminal redrawn
// at most five times a second, else one line per tenth of the work. Thread-safe.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>

namespace plantsim::batch {

class Progress {
 public:
  Progress(std::int64_t total, bool enabled);
  /// One more episode done.
  void tick();

 private:
  using Clock = std::chrono::steady_clock;
  std::int64_t total_;
  bool enabled_, tty_;
  Clock::time_point t0_;
  std::atomic<std::int64_t> done_{0};
  std::mutex mutex_;
  double last_print_ = -1;
  std::int64_t printed_decile_ = -1;
};

}  // namespace plantsim::batch
