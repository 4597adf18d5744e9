// PNG encoding: stb_image_write's PNG writer with libdeflate as its zlib compressor.
#include "raster/png.h"

#include <cstdlib>
#include <stdexcept>

#include <libdeflate.h>

namespace {

// stb's STBIW_ZLIB_COMPRESS hook takes no user pointer. The level of the call in progress on this thread
// is passed through this variable, set and reset by encode_png only; stb's own process-wide settings
// (stbi_write_png_compression_level, stbi_write_force_png_filter) are never written.
thread_local int t_deflate_level = 6;

unsigned char* libdeflate_zlib(unsigned char* data, int data_len, int* out_len, int /*stb_quality*/) {
  libdeflate_compressor* compressor = libdeflate_alloc_compressor(t_deflate_level);
  if (!compressor) return nullptr;
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor, static_cast<std::size_t>(data_len));
  auto* out = static_cast<unsigned char*>(std::malloc(bound));  // stb releases it with STBIW_FREE (free)
  std::size_t size = out ? libdeflate_zlib_compress(compressor, data, static_cast<std::size_t>(data_len), out, bound) : 0;
  libdeflate_free_compressor(compressor);
  if (size == 0) {
    std::free(out);
    return nullptr;
  }
  *out_len = static_cast<int>(size);
  return out;
}

}  // namespace

#define STBIW_ZLIB_COMPRESS libdeflate_zlib
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace raster {

std::vector<std::uint8_t> encode_png(const Image& image, const PngPlan& png) {
  struct LevelScope {  // restores the thread's level even if stb's callback throws
    int saved;
    explicit LevelScope(int level) : saved(t_deflate_level) { t_deflate_level = level; }
    ~LevelScope() { t_deflate_level = saved; }
  } scope(png.deflate_level);

  std::vector<std::uint8_t> out;
  auto append = [](void* context, void* data, int size) {
    auto* bytes = static_cast<std::uint8_t*>(data);
    static_cast<std::vector<std::uint8_t>*>(context)->insert(static_cast<std::vector<std::uint8_t>*>(context)->end(), bytes, bytes + size);
  };
  const int ok = stbi_write_png_to_func(append, &out, image.width, image.height, image.channels(),
                                        image.pixels.data(), image.width * image.channels());
  if (!ok) throw std::runtime_error("PNG encoding failed (out of memory)");
  return out;
}

}  // namespace raster
