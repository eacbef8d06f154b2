// A large block of memory for a grid that is written once and read often: mapped anonymously and
// advised for transparent huge pages, so that filling 10 MB costs five page faults rather than
// 2,500 (the particle filter's likelihood field, 10 MB on a 100 x 60 m plant, took 10 % of a
// `plantsim run` on world_N10 in small pages under `perf record`, 2 % in huge ones).
#pragma once

#include <cstddef>

namespace plantsim::util {

class HugePageBlock {
 public:
  HugePageBlock() = default;
  /// `bytes`, zeroed; throws std::bad_alloc when the system refuses them.
  explicit HugePageBlock(std::size_t bytes);
  ~HugePageBlock();
  HugePageBlock(HugePageBlock&& other) noexcept;
  HugePageBlock& operator=(HugePageBlock&& other) noexcept;
  HugePageBlock(const HugePageBlock&) = delete;
  HugePageBlock& operator=(const HugePageBlock&) = delete;

  void* data() const { return data_; }
  std::size_t size() const { return bytes_; }

 private:
  void release();

  void* mapping_ = nullptr;  // what mmap returned, and its length
  std::size_t mapped_ = 0;
  void* data_ = nullptr;  // the first huge-page boundary in it
  std::size_t bytes_ = 0;
};

}  // namespace plantsim::util
