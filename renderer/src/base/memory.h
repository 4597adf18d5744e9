// Memory for a render's large arrays (records, attributes, bins, per-vertex values). Fresh pages are what
// a large render spent most on where page faults are expensive (a VM: 26% of the sphere's cycles were the
// fault path, and two threads faulting at once ran no faster than one), so blocks of 2 MiB and more are
// mapped apart from malloc's heap and a freed one is kept for the next render, up to kKeptBytes in all:
// pages a warm server has touched once, kept as a long-running allocator keeps them (a 600k-triangle model
// at two threads uses ~140 MB of them). Smaller blocks come from malloc as usual.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

#include "raster/budget.h"

namespace raster::detail {

/// Bytes of freed large blocks kept for later renders, at most (process-wide, shared by all renders).
inline constexpr std::size_t kKeptBytes = kKeptRenderBytes;

/// A block of uninitialised storage.
struct MemoryBlock {
  void* data = nullptr;
  std::size_t bytes = 0;  ///< what it holds: at least what was asked for
};
/// At least `bytes` of uninitialised storage (see above); never null (throws std::bad_alloc).
MemoryBlock allocate_large(std::size_t bytes);
/// Frees (or keeps for reuse) a block allocate_large returned.
void free_large(MemoryBlock block) noexcept;

/// A growable array of a trivially copyable type whose new elements are not initialised: every element is
/// written before it is read, and zeroing first would touch each fresh page twice. Storage from
/// allocate_large.
template <typename T>
class PodArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  PodArray() = default;
  PodArray(PodArray&& o) noexcept { swap(o); }
  PodArray& operator=(PodArray&& o) noexcept {
    PodArray(std::move(o)).swap(*this);
    return *this;
  }
  ~PodArray() {
    if (data_) free_large(block_);
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  T& back() { return data_[size_ - 1]; }

  void reserve(std::size_t n) {
    if (n <= capacity_) return;
    const MemoryBlock fresh = allocate_large(n * sizeof(T));
    if (size_) std::memcpy(fresh.data, data_, size_ * sizeof(T));
    if (data_) free_large(block_);
    block_ = fresh;  // freed as it was given: its bytes need not be a multiple of sizeof(T)
    data_ = static_cast<T*>(fresh.data), capacity_ = fresh.bytes / sizeof(T);
  }
  /// Room for `n` more elements, growing geometrically (so that many small additions cost linear time).
  void reserve_more(std::size_t n) {
    if (size_ + n > capacity_) reserve(std::max(size_ + n, capacity_ * 2));
  }
  /// Appends `n` elements, not initialised, and returns the first.
  T* grow(std::size_t n) {
    reserve_more(n);
    T* first = data_ + size_;
    size_ += n;
    return first;
  }
  void push_back(const T& v) { *grow(1) = v; }
  void pop_back() { --size_; }
  /// Exactly `n` elements, the new ones not initialised.
  void resize_uninitialized(std::size_t n) {
    reserve(n);
    size_ = n;
  }

 private:
  void swap(PodArray& o) noexcept {
    std::swap(block_, o.block_), std::swap(data_, o.data_), std::swap(size_, o.size_),
        std::swap(capacity_, o.capacity_);
  }
  MemoryBlock block_;
  T* data_ = nullptr;
  std::size_t size_ = 0, capacity_ = 0;
};

/// Advises that [data, data + bytes), storage not yet written (a vector just reserved), be backed by huge
/// pages where the system gives them on request (THP "madvise"): its 2 MiB-aligned interior only, so nothing
/// outside the range is touched. A fresh 4 KiB page costs a fault each (about 2.5 us on the test VM: a tenth
/// of a 100 MB model's read was faults); a huge page, one per 2 MiB. Advice only: it changes no contents.
void advise_huge_pages(void* data, std::size_t bytes) noexcept;

/// Room for `n` elements in `v` (a model's positions or triangles, about to be written), its new storage
/// advised to take huge pages (advise_huge_pages) before anything is written to it.
template <typename Vector>
void reserve_huge(Vector& v, std::size_t n) {
  if (n <= v.capacity()) return;
  v.reserve(n);
  advise_huge_pages(v.data() + v.size(), (v.capacity() - v.size()) * sizeof(v[0]));
}

/// Zeroed storage of at least `bytes`, from fresh pages that are zero already (nothing is written to make
/// them so) and, for 2 MiB or more, advised to be huge pages: a hash table probed at random (a model's
/// welding table) then takes a TLB entry per 2 MiB instead of per 4 KiB, and a fault per 2 MiB. Never kept
/// for reuse.
MemoryBlock allocate_zeroed(std::size_t bytes);
/// Frees a block allocate_zeroed returned.
void free_zeroed(MemoryBlock block) noexcept;

/// A fixed number of zero-initialised elements of a trivial type, in allocate_zeroed's storage.
template <typename T>
class ZeroedArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  ZeroedArray() = default;
  explicit ZeroedArray(std::size_t n) : block_(allocate_zeroed(n * sizeof(T))), size_(n) {}
  ZeroedArray(ZeroedArray&& o) noexcept { swap(o); }
  ZeroedArray& operator=(ZeroedArray&& o) noexcept {
    ZeroedArray(std::move(o)).swap(*this);
    return *this;
  }
  ~ZeroedArray() {
    if (block_.data) free_zeroed(block_);
  }
  std::size_t size() const { return size_; }
  T* data() { return static_cast<T*>(block_.data); }
  const T* data() const { return static_cast<const T*>(block_.data); }
  T& operator[](std::size_t i) { return data()[i]; }
  const T& operator[](std::size_t i) const { return data()[i]; }

 private:
  void swap(ZeroedArray& o) noexcept { std::swap(block_, o.block_), std::swap(size_, o.size_); }
  MemoryBlock block_;
  std::size_t size_ = 0;
};

}  // namespace raster::detail
