// Starting a team of threads that tolerates the system refusing some (see the header).
#include "util/thread_team.h"

#include <system_error>
#include <thread>
#include <vector>

namespace plantsim::util {

int run_on_threads(int threads, const std::function<void()>& worker) {
  std::vector<std::thread> helpers;
  for (int t = 1; t < threads; ++t) {
    try {
      helpers.emplace_back(worker);
    } catch (const std::system_error&) {
      break;  // EAGAIN under a memory limit or a thread quota: the threads started do the work
    }
  }
  worker();
  for (std::thread& t : helpers) t.join();
  return static_cast<int>(helpers.size()) + 1;
}

}  // namespace plantsim::util
