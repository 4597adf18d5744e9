// PNG: Image -> PNG file bytes, in memory.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image.h"
#include "raster/plan.h"

namespace raster {

/// Encodes with the Up row filter and ISA-L's deflate (igzip) at `png.deflate_level`, under the colour type
/// the plan chose (8 bits per channel). Throws std::invalid_argument when that colour type does not fit
/// image.format (a plan made for another image).
std::vector<std::uint8_t> encode_png(const Image& image, const PngPlan& png);

/// The same bytes, consuming the image: its rows are filtered where they lie (no second image-sized
/// buffer), which is what a render service wants at the end of a request.
std::vector<std::uint8_t> encode_png(Image&& image, const PngPlan& png);

/// For images not made by a plan: the PngPlan a plan would choose for image.format.
std::vector<std::uint8_t> encode_png(const Image& image);
std::vector<std::uint8_t> encode_png(Image&& image);

}  // namespace raster
