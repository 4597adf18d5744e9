// stb_image_write exactly as it ships (its own deflate, try-all-five filters): the encoder baseline.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

#include "stb_stock.h"

namespace bench {

std::size_t stb_stock_png_size(const raster::Image& image) {
  int len = 0;
  unsigned char* png = stbi_write_png_to_mem(image.pixels.data(), image.width * image.channels(), image.width,
                                             image.height, image.channels(), &len);
  STBIW_FREE(png);
  return static_cast<std::size_t>(len);
}

}  // namespace bench
