// The worker pool VectorEnv steps its environments with: every index run exactly once per run,
// run after run (none left over from the one before), a job's exception rethrown to the caller
// after the others ran, and one thread alone running everything itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <future>
#include <stdexcept>
#include <system_error>
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

TEST(WorkerPool, ThreadsThatCannotStartAreLeftOutAndThePoolStillRuns) {
  // Under a thread or memory limit std::thread throws std::system_error: the pool used to let it
  // escape its constructor with started helpers still joinable (std::terminate, an abort).
  for (const int can_start : {0, 1, 2}) {
    int started = 0;
    const WorkerPool::ThreadStarter starter = [&](std::function<void()> body) {
      if (started == can_start)
        throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again));
      ++started;
      return std::thread(std::move(body));
    };
    WorkerPool pool(4, starter);
    EXPECT_EQ(pool.threads(), can_start + 1);
    for (int run = 0; run < 50; ++run) {
      std::vector<std::atomic<int>> hits(7);
      pool.run(hits.size(), [&](std::size_t i) { hits[i].fetch_add(1); });
      for (auto& h : hits) ASSERT_EQ(h.load(), 1) << can_start << " " << run;
    }
  }
}

// A helper the kernel has not scheduled (here: held at a gate before it starts) does not hold a
// run up: the caller takes every job and returns; released later, the helper takes nothing of
// the runs that are over and joins the next ones. (Every helper used to take part in every run,
// so a busy machine made two threads slower than one.)
TEST(WorkerPool, ARunNeverWaitsForAHelperThatTookNoJob) {
  std::promise<void> gate;
  std::shared_future<void> open = gate.get_future().share();
  WorkerPool pool(2, [&](std::function<void()> body) {
    return std::thread([open, body = std::move(body)] {
      open.wait();
      body();
    });
  });
  ASSERT_EQ(pool.threads(), 2);
  std::vector<std::atomic<int>> hits(8);
  auto runs = std::async(std::launch::async, [&] {
    for (int run = 0; run < 100; ++run)
      pool.run(hits.size(), [&](std::size_t i) { hits[i].fetch_add(1); });
  });
  // A hang detector, not a timing: the runs need milliseconds, the bound is generous.
  const bool prompt = runs.wait_for(std::chrono::seconds(20)) == std::future_status::ready;
  gate.set_value();  // either way: the runs then end
  runs.get();
  EXPECT_TRUE(prompt) << "a run waited for the helper held at its gate";
  for (auto& h : hits) EXPECT_EQ(h.load(), 100);
  for (int run = 0; run < 200; ++run) {
    std::vector<std::atomic<int>> again(8);
    pool.run(again.size(), [&](std::size_t i) { again[i].fetch_add(1); });
    for (auto& h : again) ASSERT_EQ(h.load(), 1) << run;
  }
}

TEST(WorkerPool, ThreadsAreCappedAtFourPerCoreAndAtTheJobs) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  EXPECT_EQ(WorkerPool::max_threads(), std::min(4 * cores, 1024));
  EXPECT_EQ(WorkerPool::threads_for(400, 400), std::min(400, WorkerPool::max_threads()));
  EXPECT_EQ(WorkerPool::threads_for(400, 3), std::min(3, WorkerPool::max_threads()));
  EXPECT_EQ(WorkerPool::threads_for(0, 400), cores);
  EXPECT_EQ(WorkerPool::threads_for(-5, 1), 1);
  // A pool asked for far more threads than the cap starts only the cap, and still runs.
  int started = 0;
  WorkerPool pool(100000, [&](std::function<void()> body) {
    ++started;
    return std::thread(std::move(body));
  });
  EXPECT_EQ(pool.threads(), WorkerPool::max_threads());
  EXPECT_EQ(started, WorkerPool::max_threads() - 1);
  std::atomic<int> ran{0};
  pool.run(1000, [&](std::size_t) { ran.fetch_add(1); });
  EXPECT_EQ(ran.load(), 1000);
}

}  // namespace
}  // namespace plantsim::util
