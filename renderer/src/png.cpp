// PNG encoding: stb_image_write's PNG writer with libdeflate as its zlib compressor.
#include "raster/png.h"

#include <cstdlib>
#include <stdexcept>

#include <libdeflate.h>

namespace {

// stb's STBIW_ZLIB_COMPRESS hook takes no user pointer. The level of the call in progress on this thread
// is passed through this variable, set and reset by encode_png only; stb's compression-level setting is
// never written.
thread_local int t_deflate_level = 1;

// One compressor per thread and level, kept: allocating one costs more than compressing a small image.
libdeflate_compressor* compressor_for(int level) {
  struct Cache {
    int level = -1;
    libdeflate_compressor* c = nullptr;
    ~Cache() { libdeflate_free_compressor(c); }
  };
  thread_local Cache cache;
  if (cache.level != level) {
    libdeflate_free_compressor(cache.c);
    cache.c = libdeflate_alloc_compressor(level);
    cache.level = cache.c ? level : -1;
  }
  return cache.c;
}

unsigned char* libdeflate_zlib(unsigned char* data, int data_len, int* out_len, int /*stb_quality*/) {
  libdeflate_compressor* compressor = compressor_for(t_deflate_level);
  if (!compressor) return nullptr;
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor, static_cast<std::size_t>(data_len));
  auto* out = static_cast<unsigned char*>(std::malloc(bound));  // stb releases it with STBIW_FREE (free)
  std::size_t size =
      out ? libdeflate_zlib_compress(compressor, data, static_cast<std::size_t>(data_len), out, bound) : 0;
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
namespace {

// PNG row filter: always "Up" instead of stb's try-all-five heuristic. Measured by bench/e2e's encoder
// sweep on the benchmark scenes: 2-3x faster and smaller files (2270/580/268 KB vs the heuristic's
// 2436/578/325 KB at libdeflate level 1, stock stb 2747/724/381 KB). The variable belongs to this file's
// private copy of stb (STB_IMAGE_WRITE_STATIC); it is set once, before the first encode, never per call.
void use_fixed_filter() {
  static const bool once = [] {
    stbi_write_force_png_filter = 2;
    return true;
  }();
  (void)once;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image, const PngPlan& png) {
  use_fixed_filter();
  struct LevelScope {  // restores the thread's level even if stb's callback throws
    int saved;
    explicit LevelScope(int level) : saved(t_deflate_level) { t_deflate_level = level; }
    ~LevelScope() { t_deflate_level = saved; }
  } scope(png.deflate_level);

  std::vector<std::uint8_t> out;
  auto append = [](void* context, void* data, int size) {
    auto* bytes = static_cast<std::uint8_t*>(data);
    static_cast<std::vector<std::uint8_t>*>(context)->insert(
        static_cast<std::vector<std::uint8_t>*>(context)->end(), bytes, bytes + size);
  };
  const int ok = stbi_write_png_to_func(append, &out, image.width, image.height, image.channels(),
                                        image.pixels.data(), image.width * image.channels());
  if (!ok) throw std::runtime_error("PNG encoding failed (out of memory)");
  return out;
}

}  // namespace raster
