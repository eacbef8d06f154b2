// The batch's progress bar (see the header).
#include "batch/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace plantsim::batch {

Progress::Progress(std::int64_t total, bool enabled)
    : total_(total), enabled_(enabled), tty_(::isatty(2)), t0_(Clock::now()) {}

void Progress::tick() {
  const std::int64_t done = ++done_;
  if (!enabled_) return;
  std::lock_guard lock(mutex_);
  const double elapsed = std::chrono::duration<double>(Clock::now() - t0_).count();
  const bool last = done == total_;
  if (tty_ ? (elapsed - last_print_ < 0.2 && !last)
           : (done * 10 / std::max<std::int64_t>(total_, 1) == printed_decile_ && !last))
    return;
  last_print_ = elapsed;
  printed_decile_ = done * 10 / std::max<std::int64_t>(total_, 1);
  const double rate = done / std::max(elapsed, 1e-9);
  const double eta = (total_ - done) / std::max(rate, 1e-9);
  const int width = 30, filled = static_cast<int>(width * done / std::max<std::int64_t>(total_, 1));
  std::fprintf(stderr, "%s[%s%s] %lld/%lld  %.1f episodes/s  ETA %.0f s%s", tty_ ? "\r" : "",
               std::string(filled, '=').c_str(), std::string(width - filled, ' ').c_str(),
               static_cast<long long>(done), static_cast<long long>(total_), rate, eta,
               tty_ && !last ? "" : "\n");
}

}  // namespace plantsim::batch
