// Block masks: an 8x8 block of pixels as 64 bits, bit 8 * row + column (row 0 at the block's top, column 0
// at its left). Coverage makes them; shade and framebuffer code read them.
#pragma once

#include <cstddef>
#include <cstdint>

namespace raster::detail {

/// Mask bits of the columns [c0, c1) of every row (0 <= c0 <= c1 <= 8).
inline std::uint64_t column_mask(int c0, int c1) {
  const std::uint64_t row = ((1u << c1) - 1) & ~((1u << c0) - 1);
  return row * 0x0101010101010101ull;
}

/// Mask bits of the rows [r0, r1) (0 <= r0 <= r1 <= 8).
inline std::uint64_t row_mask(int r0, int r1) {
  const std::uint64_t below = r1 >= 8 ? ~0ull : (1ull << (8 * r1)) - 1;
  return below & ~((1ull << (8 * r0)) - 1);
}

/// A mask for each 8x8 block of an image (block (bx, by): pixels [8 bx, 8 bx + 8) x [8 by, 8 by + 8)),
/// row-major, `columns` blocks a row: a view of storage someone else owns (edge sampling's edge pixels).
struct BlockMasks {
  const std::uint64_t* words = nullptr;
  int columns = 0;
  /// The mask of the block holding pixel (x, y) (x, y >= 0, inside the image).
  std::uint64_t at(int x, int y) const {
    return words[static_cast<std::size_t>(y / 8) * static_cast<std::size_t>(columns) +
                 static_cast<std::size_t>(x / 8)];
  }
};

}  // namespace raster::detail
