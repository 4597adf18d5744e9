#pragma once
#include <cstddef>

#include "raster/image.h"

namespace bench {
/// Encodes with stock stb_image_write (default level 8, stb's zlib) and returns the PNG's size.
std::size_t stb_stock_png_size(const raster::Image& image);
}  // namespace bench
