// Welding: corners given by position (an STL facet's three, each written out in full) become shared
// vertices, one per distinct position, so a mesh of a million vertices is drawn as a million vertices and
// not as the six million corners its facets list. Exact: two corners are one vertex when their coordinates
// are equal as numbers (0 and -0 are one), never when they are merely close.
#pragma once

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "base/budget_ask.h"
#include "base/memory.h"
#include "raster/scene.h"

namespace raster::detail {

/// Numbers vertices by position, in the order they are first seen, into `positions`: the same mesh whatever
/// the machine or thread count. An open-addressed table, at most half full, of slots that hold a vertex's
/// number and 32 bits of its position's hash: a probe passes over other vertices' slots without reading
/// their positions (a random access each, which was most of the reader's time), and compares only the one
/// whose hash matches against the output array itself (in a coherent file, a vertex written a moment before
/// and still in the cache).
class Welder {
 public:
  /// `expected`: how many distinct positions to make room for before the table grows (it grows as needed,
  /// asking `limits`' budget for the larger table before it is made, and giving the smaller one back). The
  /// first table is the caller's to ask for (table_bytes(expected)); release() gives back the last.
  Welder(std::vector<Vec3f>& positions, std::size_t expected, const Limits& limits)
      : positions_(positions), limits_(limits) {
    std::size_t slots = 1024;
    while (slots < 2 * expected) slots *= 2;
    slots_ = ZeroedArray<std::uint64_t>(slots);
    mask_ = slots - 1;
  }

  /// Bytes of a table for `expected` positions: what the welder holds beside them, before it grows.
  static std::size_t table_bytes(std::size_t expected) {
    std::size_t slots = 1024;
    while (slots < 2 * expected) slots *= 2;
    return slots * sizeof(std::uint64_t);
  }
  std::size_t table_bytes() const { return slots_.size() * sizeof(std::uint64_t); }
  /// Frees the table (the welding is done) and gives its bytes back to the budget.
  void release() {
    const auto bytes = static_cast<std::int64_t>(table_bytes());
    slots_ = {};
    detail::release(limits_, bytes);
  }

  /// The vertex at (x, y, z), made when it is new. The coordinates are finite (the caller checks).
  [[gnu::always_inline]] std::uint32_t vertex(float x, float y, float z) {
    return vertex(x, y, z, hash_of(x, y, z));
  }
  /// The same, with the position's hash_of already known (a parallel weld sorts corners by it).
  [[gnu::always_inline]] std::uint32_t vertex(float x, float y, float z, std::uint64_t h) {
    const std::uint32_t a = bits(x), b = bits(y), c = bits(z);
    const std::uint64_t tag = h >> 32 << 32;
    for (std::size_t i = h & mask_;; i = (i + 1) & mask_) {
      const std::uint64_t s = slots_[i];
      if (s == 0) return add(i, tag, x, y, z);
      if ((s & ~0xFFFFFFFFull) != tag) continue;
      const auto v = static_cast<std::uint32_t>(s) - 1;
      const Vec3f& p = positions_[v];
      if (bits(p.x) == a && bits(p.y) == b && bits(p.z) == c) return v;
    }
  }

  /// The vertex at (x, y, z) when there is one, else UINT32_MAX (nothing is made).
  std::uint32_t find(float x, float y, float z) const {
    const std::uint32_t a = bits(x), b = bits(y), c = bits(z);
    const std::uint64_t h = hash(a, b, c), tag = h >> 32 << 32;
    for (std::size_t i = h & mask_;; i = (i + 1) & mask_) {
      const std::uint64_t s = slots_[i];
      if (s == 0) return UINT32_MAX;
      if ((s & ~0xFFFFFFFFull) != tag) continue;
      const auto v = static_cast<std::uint32_t>(s) - 1;
      const Vec3f& p = positions_[v];
      if (bits(p.x) == a && bits(p.y) == b && bits(p.z) == c) return v;
    }
  }

  /// Where vertex(x, y, z) will look first, for a prefetch a few corners ahead.
  const std::uint64_t* slot_of(float x, float y, float z) const { return slot_of(hash_of(x, y, z)); }
  const std::uint64_t* slot_of(std::uint64_t h) const { return slots_.data() + (h & mask_); }

  /// The hash the table files (x, y, z) under: equal positions (0 and -0 alike), equal hashes. Its low bits
  /// pick the slot; its high 32 are the slot's tag.
  static std::uint64_t hash_of(float x, float y, float z) { return hash(bits(x), bits(y), bits(z)); }

 private:
  // A coordinate's bits with -0 taken as 0: equal numbers, equal bits (NaN never reaches here).
  static std::uint32_t bits(float f) {
    const std::uint32_t u = std::bit_cast<std::uint32_t>(f);
    return u == 0x80000000u ? 0 : u;
  }
  static std::uint64_t hash(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint64_t h =
        (std::uint64_t{a} << 32 | b) * 0x9E3779B97F4A7C15ull ^ std::uint64_t{c} * 0xC2B2AE3D27D4EB4Full;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    return h ^ h >> 32;
  }
  std::uint32_t add(std::size_t slot, std::uint64_t tag, float x, float y, float z) {
    const auto v = static_cast<std::uint32_t>(positions_.size());
    positions_.push_back({x, y, z});
    slots_[slot] = tag | (v + 1);
    if (2 * positions_.size() > slots_.size()) grow();
    return v;
  }
  // Twice the slots, every vertex hashed in again (from the positions: the old table is given back first).
  void grow() {
    const std::size_t slots = 2 * slots_.size();
    release();
    detail::reserve(limits_, static_cast<std::int64_t>(slots * sizeof(std::uint64_t)),
                    [] { return std::string("the model's welding table"); });
    slots_ = ZeroedArray<std::uint64_t>(slots);
    mask_ = slots_.size() - 1;
    for (std::uint32_t v = 0; v < positions_.size(); ++v) {
      const Vec3f& p = positions_[v];
      const std::uint64_t h = hash(bits(p.x), bits(p.y), bits(p.z));
      std::size_t i = h & mask_;
      while (slots_[i]) i = (i + 1) & mask_;
      slots_[i] = h >> 32 << 32 | (v + 1);
    }
  }

  std::vector<Vec3f>& positions_;
  const Limits& limits_;
  /// 0: empty; else the high 32 bits of the position's hash, and the vertex's number + 1 in the low 32.
  ZeroedArray<std::uint64_t> slots_;
  std::size_t mask_ = 0;  ///< slots_.size() - 1 (a power of two)
};

}  // namespace raster::detail
