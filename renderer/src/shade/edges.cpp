#include "shade/edges.h"

#include <algorithm>
#include <bit>
#include <cstddef>

namespace raster::detail {

bool EdgePixels::any_in(Rect rect) const {
  const int bx0 = rect.x0 / kBlock, bx1 = (rect.x1 - 1) / kBlock;
  for (int by = rect.y0 / kBlock; by * kBlock < rect.y1; ++by) {
    const std::uint64_t rows =
        row_mask(std::max(0, rect.y0 - by * kBlock), std::min(kBlock, rect.y1 - by * kBlock));
    const std::uint64_t* row = masks.data() + static_cast<std::size_t>(by) * columns;
    for (int bx = bx0; bx <= bx1; ++bx)
      if (row[bx] & rows &
          column_mask(std::max(0, rect.x0 - bx * kBlock), std::min(kBlock, rect.x1 - bx * kBlock)))
        return true;
  }
  return false;
}

EdgePixels find_edge_pixels(const Image& image, StopMeter& meter, int contrast) {
  EdgePixels out;
  out.columns = (image.width + kBlock - 1) / kBlock;
  out.rows = (image.height + kBlock - 1) / kBlock;
  out.masks.assign(static_cast<std::size_t>(out.columns) * out.rows, 0);
  const int c = image.channels();
  const std::size_t stride = static_cast<std::size_t>(image.width) * c;
  // Every 2x2 quad of pixels (x, x + 1) x (y, y + 1) compares its six pairs, so each pair of neighbours in
  // the eight directions is compared by some quad, and a quad that differs marks its four pixels. A
  // one-pixel-wide (tall) image has quads one pixel wide (tall): the pixel is its own neighbour there.
  const int across = std::max(image.width - 1, 1), down = std::max(image.height - 1, 1);
  const std::size_t right = image.width > 1 ? static_cast<std::size_t>(c) : 0;
  const std::size_t below = image.height > 1 ? stride : 0;
  const std::size_t bytes = static_cast<std::size_t>(across) * c;
  std::vector<std::uint8_t> differs(bytes);  // per channel of each quad of the row: 1 when some pair differs
  const auto limit = static_cast<std::uint8_t>(std::clamp(contrast, 0, 255));
  for (int y = 0; y < down; ++y) {
    if (meter.add(image.width)) break;
    const std::uint8_t* a = image.pixels.data() + static_cast<std::size_t>(y) * stride;
    const std::uint8_t* b = a + below;
    // A byte loop the compiler vectorises: the widest of a quad's six pairs is its largest less its least.
    std::uint8_t any = 0;
    for (std::size_t i = 0; i < bytes; ++i) {
      const std::uint8_t p = a[i], q = a[i + right], r = b[i], s = b[i + right];
      const std::uint8_t hi = std::max(std::max(p, q), std::max(r, s));
      const std::uint8_t lo = std::min(std::min(p, q), std::min(r, s));
      differs[i] = static_cast<std::uint8_t>(hi - lo > limit);
      any |= differs[i];
    }
    if (!any) continue;  // most rows of a picture's background
    const int pixel_rows[2] = {y, std::min(y + 1, image.height - 1)};
    for (int bx = 0; bx < out.columns; ++bx) {
      // Quads x in [8 bx - 1, 8 bx + 7] hold a pixel of block column bx; most blocks have no edge.
      const int x0 = std::max(0, bx * kBlock - 1), x1 = std::min(across, bx * kBlock + kBlock);
      const std::uint8_t* d = differs.data() + static_cast<std::size_t>(x0) * c;
      const std::size_t n = static_cast<std::size_t>(x1 - x0) * c;
      if (std::find(d, d + n, 1) == d + n) continue;
      std::uint64_t byte = 0;  // the block's pixels in this row (and the next) that a differing quad holds
      for (int x = x0; x < x1; ++x) {
        std::uint8_t quad = 0;
        for (int k = 0; k < c; ++k) quad |= differs[static_cast<std::size_t>(x) * c + k];
        if (!quad) continue;
        for (const int px : {x, std::min(x + 1, image.width - 1)})
          if (px / kBlock == bx) byte |= std::uint64_t{1} << (px % kBlock);
      }
      for (const int py : pixel_rows)
        out.masks[static_cast<std::size_t>(py / kBlock) * out.columns + bx] |= byte << (8 * (py % kBlock));
    }
  }
  out.bytes = static_cast<std::int64_t>(out.masks.size() * sizeof(std::uint64_t) + differs.size());
  for (const std::uint64_t m : out.masks) out.blocks += m != 0, out.pixels += std::popcount(m);
  return out;
}

}  // namespace raster::detail
