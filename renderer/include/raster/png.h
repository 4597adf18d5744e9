// PNG: Image -> PNG file bytes, in memory.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image.h"
#include "raster/plan.h"

namespace raster {

/// Encodes with the Up row filter and ISA-L's deflate (igzip) at `png.deflate_level`. The colour type
/// follows image.format (grey, grey+alpha, RGB or RGBA, 8 bits per channel).
std::vector<std::uint8_t> encode_png(const Image& image, const PngPlan& png = {});

/// The same bytes, consuming the image: its rows are filtered where they lie (no second image-sized
/// buffer), which is what a render service wants at the end of a request.
std::vector<std::uint8_t> encode_png(Image&& image, const PngPlan& png = {});

}  // namespace raster
