// HugePageBlock: an anonymous private mapping, its huge-page-aligned part advised MADV_HUGEPAGE
// (the advice is a hint: where the kernel declines it the memory is the same, in small pages).
#include "util/huge_page_block.h"

#include <sys/mman.h>

#include <cstdint>
#include <new>
#include <utility>

namespace plantsim::util {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
}

HugePageBlock::HugePageBlock(std::size_t bytes) : bytes_(bytes) {
  if (bytes == 0) return;
  mapped_ = bytes + kHugePage;
  mapping_ = mmap(nullptr, mapped_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapping_ == MAP_FAILED) {
    mapping_ = nullptr;
    throw std::bad_alloc();
  }
  const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(mapping_);
  const std::uintptr_t aligned = (start + kHugePage - 1) & ~(kHugePage - 1);
  data_ = reinterpret_cast<void*>(aligned);
  madvise(data_, bytes, MADV_HUGEPAGE);
}

HugePageBlock::~HugePageBlock() { release(); }

HugePageBlock::HugePageBlock(HugePageBlock&& other) noexcept
    : mapping_(std::exchange(other.mapping_, nullptr)),
      mapped_(std::exchange(other.mapped_, 0)),
      data_(std::exchange(other.data_, nullptr)),
      bytes_(std::exchange(other.bytes_, 0)) {}

HugePageBlock& HugePageBlock::operator=(HugePageBlock&& other) noexcept {
  if (this != &other) {
    release();
    mapping_ = std::exchange(other.mapping_, nullptr);
    mapped_ = std::exchange(other.mapped_, 0);
    data_ = std::exchange(other.data_, nullptr);
    bytes_ = std::exchange(other.bytes_, 0);
  }
  return *this;
}

void HugePageBlock::release() {
  if (mapping_) munmap(mapping_, mapped_);
  mapping_ = data_ = nullptr;
  mapped_ = bytes_ = 0;
}

}  // namespace plantsim::util
