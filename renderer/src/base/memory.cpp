#include "base/memory.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace raster::detail {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

// Large blocks are mapped directly rather than taken from malloc: a kept block then holds no part of the
// heap that the rest of a request (the model's parse, the image, the PNG) reuses from request to request.
void* map_block(std::size_t bytes) {
#if defined(__linux__)
  // One alignment more than needed, then the unaligned ends given back: aligned blocks can take huge pages
  // where the system gives them to every mapping (THP "always"). Not advised with MADV_HUGEPAGE: with blocks
  // kept it gains nothing measurable (the sphere at 2 threads, 68-72 ms either way).
  const std::size_t span = bytes + kHugePage;
  void* p = ::mmap(nullptr, span, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t aligned = (at + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > at) ::munmap(p, aligned - at);
  if (const std::size_t tail = at + span - (aligned + bytes))
    ::munmap(reinterpret_cast<void*>(aligned + bytes), tail);
  return reinterpret_cast<void*>(aligned);
#else
  void* p = std::aligned_alloc(kHugePage, bytes);
  if (!p) throw std::bad_alloc();
  return p;
#endif
}

void unmap_block(MemoryBlock b) {
#if defined(__linux__)
  ::munmap(b.data, b.bytes);
#else
  std::free(b.data);
#endif
}

// Freed large blocks, oldest first. A request takes the smallest kept block that holds it and is at most
// twice its size (a larger one would hold pages idle that another render could use), the newest of equals
// (the likeliest still in a cache).
class KeptBlocks {
 public:
  MemoryBlock take(std::size_t bytes) {
    const std::lock_guard lock(mutex_);
    std::size_t best = blocks_.size();
    for (std::size_t i = 0; i < blocks_.size(); ++i)
      if (blocks_[i].bytes >= bytes && blocks_[i].bytes <= 2 * bytes &&
          (best == blocks_.size() || blocks_[i].bytes <= blocks_[best].bytes))
        best = i;
    if (best == blocks_.size()) return {};
    const MemoryBlock b = blocks_[best];
    blocks_.erase(blocks_.begin() + static_cast<std::ptrdiff_t>(best));
    kept_ -= b.bytes;
    return b;
  }
  void keep(MemoryBlock b) {
    if (b.bytes > kKeptBytes) return unmap_block(b);
    const std::lock_guard lock(mutex_);
    while (kept_ + b.bytes > kKeptBytes) {  // the oldest go first
      unmap_block(blocks_.front());
      kept_ -= blocks_.front().bytes;
      blocks_.erase(blocks_.begin());
    }
    blocks_.push_back(b);
    kept_ += b.bytes;
  }
  ~KeptBlocks() {
    for (const MemoryBlock& b : blocks_) unmap_block(b);
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
  return {map_block(rounded), rounded};
}

void free_large(MemoryBlock block) noexcept {
  if (block.bytes < kHugePage) return std::free(block.data);
  kept_blocks().keep(block);
}

void advise_huge_pages(void* data, std::size_t bytes) noexcept {
#if defined(__linux__)
  const auto at = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (at + kHugePage - 1) / kHugePage * kHugePage,
                       end = (at + bytes) / kHugePage * kHugePage;
  if (end > first) ::madvise(reinterpret_cast<void*>(first), end - first, MADV_HUGEPAGE);
#else
  (void)data, (void)bytes;
#endif
}

MemoryBlock allocate_zeroed(std::size_t bytes) {
  if (bytes < kHugePage) {
    if (void* p = std::calloc(std::max<std::size_t>(bytes, 1), 1)) return {p, bytes};
    throw std::bad_alloc();
  }
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* p = map_block(rounded);
#if defined(__linux__)
  ::madvise(p, rounded, MADV_HUGEPAGE);  // advice only: without THP the pages are small, and still zero
#else
  std::memset(p, 0, rounded);
#endif
  return {p, rounded};
}

void free_zeroed(MemoryBlock block) noexcept {
  if (block.bytes < kHugePage) return std::free(block.data);
  unmap_block(block);
}

}  // namespace raster::detail
