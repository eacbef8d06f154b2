// Running one worker function on several threads that share their work through the worker's
// own counter (batch episodes, tuning candidates): as many threads as could be started, the
// caller among them, so that a system refusing threads (a memory limit, a thread quota) slows a
// run down instead of aborting it.
#pragma once

#include <functional>

namespace plantsim::util {

/// Runs `worker` on up to `threads` threads (at least the calling thread) and joins them all.
/// A thread the system refuses to start is skipped: the worker must take its work from a shared
/// counter, so that any number of threads finishes all of it. Returns how many threads ran it.
/// Exceptions are the worker's business (it must not throw out of itself).
int run_on_threads(int threads, const std::function<void()>& worker);

}  // namespace plantsim::util
