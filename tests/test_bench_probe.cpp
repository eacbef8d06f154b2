// The benchmark's memory probe: the peak it reports after a reset grows by what a phase touches,
// and not by what an earlier phase used and freed.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "bench/memory_probe.h"

namespace plantsim::bench {
namespace {

void touch(std::size_t bytes) {
  auto block = std::make_unique<char[]>(bytes);
  std::memset(block.get(), 1, bytes);
  volatile char sink = block[bytes - 1];
  (void)sink;
}

TEST(MemoryProbe, APhasesPeakIsWhatItTouchedNotWhatCameBefore) {
  ASSERT_TRUE(current_memory_mb().has_value());
  touch(200u << 20);  // an earlier phase: 200 MB, freed
  if (!reset_peak_memory()) GTEST_SKIP() << "this kernel does not allow resetting the peak";
  const double before = *current_memory_mb();
  EXPECT_LT(*peak_memory_mb() - before, 20.0);  // the earlier 200 MB are not this phase's
  touch(64u << 20);
  const double grown = *peak_memory_mb() - before;
  EXPECT_GT(grown, 60.0);
  EXPECT_LT(grown, 100.0);
}

}  // namespace
}  // namespace plantsim::bench
