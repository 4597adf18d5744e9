#include "memory.h"

#include <cstdlib>
#include <mutex>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace raster::detail {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

// Freed large blocks, oldest first. A request takes the smallest kept block that holds it and is at most
// twice its size (a larger one would hold pages idle that another render could use).
class KeptBlocks {
 public:
  MemoryBlock take(std::size_t bytes) {
    const std::lock_guard lock(mutex_);
    std::size_t best = blocks_.size();
    for (std::size_t i = 0; i < blocks_.size(); ++i)
      if (blocks_[i].bytes >= bytes && blocks_[i].bytes <= 2 * bytes &&
          (best == blocks_.size() || blocks_[i].bytes < blocks_[best].bytes))
        best = i;
    if (best == blocks_.size()) return {};
    const MemoryBlock b = blocks_[best];
    blocks_.erase(blocks_.begin() + static_cast<std::ptrdiff_t>(best));
    kept_ -= b.bytes;
    return b;
  }
  void keep(MemoryBlock b) {
    if (b.bytes > kKeptBytes) return std::free(b.data);
    const std::lock_guard lock(mutex_);
    while (kept_ + b.bytes > kKeptBytes) {  // the oldest go first
      std::free(blocks_.front().data);
      kept_ -= blocks_.front().bytes;
      blocks_.erase(blocks_.begin());
    }
    blocks_.push_back(b);
    kept_ += b.bytes;
  }
  ~KeptBlocks() {
    for (const MemoryBlock& b : blocks_) std::free(b.data);
  }

 private:
  std::mutex mutex_;
  std::vector<MemoryBlock> blocks_;
  std::size_t kept_ = 0;
};

KeptBlocks& kept_blocks() {
  static KeptBlocks blocks;
  return blocks;
}

}  // namespace

MemoryBlock allocate_large(std::size_t bytes) {
  if (bytes < kHugePage) {
    if (void* p = std::malloc(std::max<std::size_t>(bytes, 1))) return {p, bytes};
    throw std::bad_alloc();
  }
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  if (const MemoryBlock kept = kept_blocks().take(rounded); kept.data) return kept;
  void* p = std::aligned_alloc(kHugePage, rounded);
  if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  ::madvise(p, rounded, MADV_HUGEPAGE);  // advice only: without THP the pages are ordinary ones
#endif
  return {p, rounded};
}

void free_large(MemoryBlock block) noexcept {
  if (block.bytes < kHugePage) return std::free(block.data);
  kept_blocks().keep(block);
}

}  // namespace raster::detail
