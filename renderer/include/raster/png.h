// PNG: Image -> PNG file bytes, in memory.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image.h"
#include "raster/plan.h"

namespace raster {

/// Encodes with the Up row filter and libdeflate's zlib compressor at `png.deflate_level`. The colour type
/// follows image.format (grey, grey+alpha, RGB or RGBA, 8 bits per channel).
std::vector<std::uint8_t> encode_png(const Image& image, const PngPlan& png = {});

}  // namespace raster
