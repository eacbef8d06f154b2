// The worker pool VectorEnv steps its environments with: every index run exactly once per run,
// run after run (none left over from the one before), a job's exception rethrown to the caller
// after the others ran, and one thread alone running everything itself.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "util/worker_pool.h"

namespace plantsim::util {
namespace {

TEST(WorkerPool, EveryIndexOnceRunAfterRunAndExceptionsReachTheCaller) {
  for (const int threads : {1, 2, 4}) {
    WorkerPool pool(threads);
    for (int run = 0; run < 300; ++run) {
      const std::size_t n = static_cast<std::size_t>(run % 9);
      std::vector<std::atomic<int>> hits(n);
      pool.run(n, [&](std::size_t i) { hits[i].fetch_add(1); });
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i].load(), 1) << threads << " " << run;
    }
    std::atomic<int> ran{0};
    EXPECT_THROW(pool.run(6,
                          [&](std::size_t i) {
                            ran.fetch_add(1);
                            if (i == 2) throw std::runtime_error("job 2");
                          }),
                 std::runtime_error);
    EXPECT_EQ(ran.load(), 6);
    std::atomic<int> after{0};
    pool.run(3, [&](std::size_t) { after.fetch_add(1); });  // usable after a failure
    EXPECT_EQ(after.load(), 3);
  }
  WorkerPool alone(1);
  const std::thread::id caller = std::this_thread::get_id();
  alone.run(4, [&](std::size_t) { EXPECT_EQ(std::this_thread::get_id(), caller); });
}

}  // namespace
}  // namespace plantsim::util
