// Tile storage: RenderPlan::tile_storage -> one render thread's buffers, allocated to exactly the sizes the
// plan worked out (and counted against the limit). A thread draws one tile at a time in them: the tile's
// colour, its depth (the only depth buffer there is), the samples' colours and the union accumulation.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

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

}  // namespace raster::detail
