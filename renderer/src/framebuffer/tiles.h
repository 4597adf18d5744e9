// Tile storage: RenderPlan::tile_storage -> one render thread's buffers, allocated to exactly the sizes the
// plan worked out (and counted against the limit): the tile's colour, its depth (the only depth buffer there
// is), the samples' colours and the union accumulation. A thread draws one tile at a time in them: open_tile
// (image + tile rectangle -> a cleared Surface over the storage), then close_tile (the finished colour back
// into the image); image_surface is the Surface of tiles drawn in place.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "base/grid.h"
#include "base/masks.h"
#include "framebuffer/surface.h"
#include "raster/image.h"
#include "raster/plan.h"

namespace raster::detail {

/// One thread's tile storage. Sizes are the plan's; an unused buffer is empty.
struct TileStorage {
  std::vector<std::uint8_t> color;  ///< the tile's colour, channels a pixel (empty when tiles draw in place)
  std::vector<float> depth;         ///< a plane of z / w per sample (3D)
  std::vector<float> coverage;      ///< area coverage: union primitives' accumulation, kUnionFloats a pixel
  /// Multisampling: a colour plane per sample, written before it is read (so never cleared, nor zeroed here).
  std::unique_ptr<std::uint8_t[]> samples;
  std::size_t sample_bytes = 0;         ///< bytes at `samples`
  std::vector<std::uint64_t> expanded;  ///< a word per block: which pixels' samples differ (or, area: are
                                        ///< accumulated in)
  std::int64_t shaded = 0;              ///< pixels this thread shaded, for RenderStats (Surface::shaded)

  explicit TileStorage(const TileStoragePlan& plan);
  /// Bytes allocated, for RenderStats::pixel_bytes (checked against the plan by the tests).
  std::int64_t bytes() const;
};

/// Where the image's pixel (x, y) starts in Image::pixels, for code compiled for its C channels.
template <int C>
std::size_t image_offset(const Image& image, int x, int y) {
  return (static_cast<std::size_t>(y) * image.width + x) * C;
}

/// Tiles drawn in place (RenderPlan::tiles_in_place): the image itself is the surface, its rows whole blocks
/// wide; `storage` only counts the pixels shaded.
template <int C>
Surface image_surface(Image& image, const RenderPlan& plan, TileStorage& storage) {
  Surface surface{image.pixels.data(), nullptr, nullptr, image.width, 0, 0, C};
  surface.shaded = &storage.shaded;
  surface.simd = plan.simd;
  return surface;
}

/// The surface over `storage` for tile `rect`, nothing cleared yet: its buffers, the strides and the plan's
/// kernels. Rows of the storage are whole blocks wide (and planes whole blocks tall): a block at the image's
/// edge stays in its own rows.
template <int C>
Surface tile_surface(TileStorage& storage, const RenderPlan& plan, Rect rect) {
  const int stride = (rect.x1 - rect.x0 + kBlock - 1) / kBlock * kBlock;
  const int block_rows = (rect.y1 - rect.y0 + kBlock - 1) / kBlock * kBlock;
  Surface surface{storage.color.data(),
                  storage.depth.empty() ? nullptr : storage.depth.data(),
                  storage.coverage.empty() ? nullptr : storage.coverage.data(),
                  stride,
                  rect.x0,
                  rect.y0,
                  C};
  surface.shaded = &storage.shaded;
  surface.simd = plan.simd;
  surface.plane = static_cast<std::size_t>(stride) * block_rows;
  return surface;
}

/// The surface of tile `rect` in `storage`, ready to draw: its colour filled from the image (which holds the
/// background there), depth and the expanded bits cleared, the plan's coverage mode set and, multisampled,
/// its sample planes and `pattern` (the plan's sample positions). Edge sampling's first pass is aliased:
/// its surface has centre coverage (open_edge_tile opens the second).
template <int C>
Surface open_tile(TileStorage& storage, const RenderPlan& plan, const SamplePoint* pattern, Rect rect,
                  const Image& image) {
  const int w = rect.x1 - rect.x0;
  Surface surface = tile_surface<C>(storage, plan, rect);
  surface.coverage_mode = plan.coverage == Coverage::edge_samples ? Coverage::centre : plan.coverage;
  if (plan.coverage == Coverage::samples) {
    surface.sample_count = plan.samples;
    surface.pattern = pattern;
    surface.samples = storage.samples.get();
  }
  if (!storage.expanded.empty()) {
    surface.expanded = storage.expanded.data();
    std::fill_n(surface.expanded, surface.plane / 64, 0);
  }
  const std::size_t row_bytes = static_cast<std::size_t>(w) * C;
  for (int y = rect.y0; y < rect.y1; ++y)
    std::memcpy(surface.pixel(rect.x0, y), image.pixels.data() + image_offset<C>(image, rect.x0, y),
                row_bytes);
  if (surface.depth) std::fill_n(surface.depth, surface.plane * surface.sample_count, 0.0f);
  if (plan.keep_samples && plan.coverage == Coverage::samples) {  // every pixel a colour per sample
    surface.keep_samples = true;
    std::fill_n(surface.expanded, surface.plane / 64, ~std::uint64_t{0});
    for (std::size_t at = 0; at < surface.plane; ++at) surface.expand<C>(at);
  }
  return surface;
}

/// Edge sampling's second pass over tile `rect`: a multisampled surface (the plan's samples at `pattern`)
/// whose blocks holding a pixel of `only` (a mask per block of the image) hold the background colour
/// `background` (C bytes), their depth (3D) cleared in every sample plane. Only the pixels of `only` are
/// copied back (close_edge_tile); the rest of those blocks is scratch.
template <int C>
Surface open_edge_tile(TileStorage& storage, const RenderPlan& plan, const SamplePoint* pattern, Rect rect,
                       BlockMasks only, const std::uint8_t* background) {
  Surface surface = tile_surface<C>(storage, plan, rect);
  surface.coverage = nullptr;  // no union coverage: edge sampling never covers by area
  surface.coverage_mode = Coverage::samples;
  surface.sample_count = plan.samples;
  surface.pattern = pattern;
  surface.samples = storage.samples.get();
  surface.expanded = storage.expanded.data();
  surface.keep_samples = plan.keep_samples;
  std::fill_n(surface.expanded, surface.plane / 64, 0);
  for (int y0 = rect.y0; y0 < rect.y1; y0 += kBlock)
    for (int x0 = rect.x0; x0 < rect.x1; x0 += kBlock) {
      const std::uint64_t mask = only.at(x0, y0);
      if (!mask) continue;
      const int x1 = std::min(rect.x1, x0 + kBlock), y1 = std::min(rect.y1, y0 + kBlock);
      for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) std::memcpy(surface.pixel<C>(x, y), background, C);
        for (int s = 0; surface.depth && s < surface.sample_count; ++s)  // 2D has no depth
          std::fill_n(surface.depth + static_cast<std::size_t>(s) * surface.plane + surface.index(x0, y),
                      x1 - x0, 0.0f);
      }
      if (plan.keep_samples) {  // the test hook: every pixel keeps a colour per sample from the start
        surface.expanded_bits(x0, y0) = mask;
        for (std::uint64_t m = mask; m; m &= m - 1)
          surface.expand<C>(
              surface.index(x0 + std::countr_zero(m) % kBlock, y0 + std::countr_zero(m) / kBlock));
      }
    }
  return surface;
}

/// Copies the pixels of `only` inside tile `rect` from `surface` back into the image.
template <int C>
void close_edge_tile(const Surface& surface, Rect rect, BlockMasks only, Image& image) {
  for (int y0 = rect.y0; y0 < rect.y1; y0 += kBlock)
    for (int x0 = rect.x0; x0 < rect.x1; x0 += kBlock)
      for (std::uint64_t m = only.at(x0, y0); m; m &= m - 1) {
        const int x = x0 + std::countr_zero(m) % kBlock, y = y0 + std::countr_zero(m) / kBlock;
        std::memcpy(image.pixels.data() + image_offset<C>(image, x, y), surface.pixel<C>(x, y), C);
      }
}

/// Copies the finished (resolved) colour of tile `rect` from `surface` back into the image.
template <int C>
void close_tile(const Surface& surface, Rect rect, Image& image) {
  const std::size_t row_bytes = static_cast<std::size_t>(rect.x1 - rect.x0) * C;
  for (int y = rect.y0; y < rect.y1; ++y)
    std::memcpy(image.pixels.data() + image_offset<C>(image, rect.x0, y), surface.pixel(rect.x0, y),
                row_bytes);
}

}  // namespace raster::detail
