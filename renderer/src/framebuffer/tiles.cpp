#include "framebuffer/tiles.h"

namespace raster::detail {

TileStorage::TileStorage(const TileStoragePlan& plan)
    : color(static_cast<std::size_t>(plan.color_bytes)),
      depth(static_cast<std::size_t>(plan.depth_floats)),
      coverage(static_cast<std::size_t>(plan.coverage_floats)),
      sample_bytes(static_cast<std::size_t>(plan.sample_bytes)),
      expanded(static_cast<std::size_t>(plan.expanded_words)) {
  if (sample_bytes) samples.reset(new std::uint8_t[sample_bytes]);
}

std::int64_t TileStorage::bytes() const {
  return static_cast<std::int64_t>(color.size() + (depth.size() + coverage.size()) * sizeof(float) +
                                   sample_bytes + expanded.size() * sizeof(std::uint64_t));
}

}  // namespace raster::detail
