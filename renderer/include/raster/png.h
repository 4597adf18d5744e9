// PNG: Image -> PNG file bytes, in memory.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image.h"
#include "raster/plan.h"

namespace raster {

/// Encodes with stb_image_write's PNG writer and libdeflate's compressor. The colour type follows
/// image.format; `png.deflate_level` is the libdeflate level.
std::vector<std::uint8_t> encode_png(const Image& image, const PngPlan& png = {});

}  // namespace raster
