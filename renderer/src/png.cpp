// PNG encoding: the Up row filter, libdeflate's zlib compressor and CRC, written straight into one buffer.
//
// A PNG is a signature and three chunks here (IHDR, one IDAT, IEND), so the container is a few lines; the
// cost is all in filtering and compressing. This used to be stb_image_write with libdeflate hooked in as
// its zlib: stb's byte-at-a-time CRC over the compressed data and its two copies of the output took a
// sixth of the encode (perf, bench/micro encode/*), and its filter choice and our deflate level had to
// reach it through a process-wide setting and a thread-local. The bytes are the ones that writer produced
// with filter Up forced (tests/render_test.cpp checks them against stb_image's decoder).
#include "raster/png.h"

#include <cstring>
#include <memory>
#include <new>
#include <stdexcept>

#include <libdeflate.h>

namespace raster {
namespace {

// One compressor per thread and level, kept: allocating one (hundreds of KB of tables) costs more than
// compressing a small image. A cache, not a setting: every call names its level.
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
  if (!cache.c) throw std::bad_alloc();
  return cache.c;
}

void put_u32(std::uint8_t* p, std::uint32_t v) {
  p[0] = static_cast<std::uint8_t>(v >> 24), p[1] = static_cast<std::uint8_t>(v >> 16);
  p[2] = static_cast<std::uint8_t>(v >> 8), p[3] = static_cast<std::uint8_t>(v);
}

// A chunk whose data is already in place at `at` + 8: writes its length and type before the data and its
// CRC (over type and data) after; returns the position after the chunk.
std::size_t finish_chunk(std::vector<std::uint8_t>& out, std::size_t at, const char (&type)[5],
                         std::size_t length) {
  put_u32(out.data() + at, static_cast<std::uint32_t>(length));
  std::memcpy(out.data() + at + 4, type, 4);
  const auto crc = static_cast<std::uint32_t>(libdeflate_crc32(0, out.data() + at + 4, length + 4));
  put_u32(out.data() + at + 8 + length, crc);
  return at + 12 + length;
}

// The PNG of filtered rows (a filter byte, then the row, per row). The compressed data goes to a buffer
// of libdeflate's bound, of which only what is written gets memory pages; the rows are released before
// the file is assembled, so at most the rows and the compressed data exist at once.
std::vector<std::uint8_t> write_png(const Image& image, std::vector<std::uint8_t>&& filtered, int level) {
  libdeflate_compressor* compressor = compressor_for(level);
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor, filtered.size());
  const std::unique_ptr<std::uint8_t[]> compressed(new std::uint8_t[bound]);  // not zeroed: not touched
  const std::size_t size =
      libdeflate_zlib_compress(compressor, filtered.data(), filtered.size(), compressed.get(), bound);
  if (size == 0) throw std::runtime_error("PNG encoding failed: compressed data exceeded its bound");
  std::vector<std::uint8_t>().swap(filtered);

  static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  static constexpr std::uint8_t kColorType[5] = {0, 0, 4, 2, 6};  // by channels: grey, grey+alpha, RGB, RGBA
  constexpr std::size_t kIhdr = 13;
  std::vector<std::uint8_t> out(8 + (12 + kIhdr) + (12 + size) + 12);
  std::memcpy(out.data(), kSignature, 8);
  std::uint8_t* ihdr = out.data() + 8 + 8;
  put_u32(ihdr, static_cast<std::uint32_t>(image.width));
  put_u32(ihdr + 4, static_cast<std::uint32_t>(image.height));
  ihdr[8] = 8;  // bits per channel
  ihdr[9] = kColorType[image.channels()];
  ihdr[10] = ihdr[11] = ihdr[12] = 0;  // deflate, adaptive filtering, no interlace
  std::size_t at = finish_chunk(out, 8, "IHDR", kIhdr);
  std::memcpy(out.data() + at + 8, compressed.get(), size);
  at = finish_chunk(out, at, "IDAT", size);
  finish_chunk(out, at, "IEND", 0);
  return out;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image, const PngPlan& png) {
  // Filter "Up" on every row (the first has a row of zeros above it, so its bytes go as they are): one
  // fixed filter instead of trying all five per row. Measured on the benchmark scenes: 2-3x faster than
  // stb's heuristic and smaller files at libdeflate level 1 (2270/580/268 KB against 2436/578/325 KB).
  const std::size_t stride = static_cast<std::size_t>(image.width) * image.channels();
  const std::size_t height = static_cast<std::size_t>(image.height);
  std::vector<std::uint8_t> filtered(height * (stride + 1));
  for (std::size_t y = 0; y < height; ++y) {
    std::uint8_t* out = filtered.data() + y * (stride + 1);
    const std::uint8_t* row = image.pixels.data() + y * stride;
    out[0] = 2;
    if (y == 0) {
      std::memcpy(out + 1, row, stride);
      continue;
    }
    const std::uint8_t* above = row - stride;
    for (std::size_t i = 0; i < stride; ++i) out[1 + i] = static_cast<std::uint8_t>(row[i] - above[i]);
  }
  return write_png(image, std::move(filtered), png.deflate_level);
}

std::vector<std::uint8_t> encode_png(Image&& image, const PngPlan& png) {
  // The same rows, filtered where they lie: each row moves y + 1 bytes up to make room for the filter
  // bytes, so rows go bottom to top (the row above is still unfiltered when a row needs it), and within
  // a row 16 bytes are read before they are written, from the end down, so no unread byte is overwritten.
  using Bytes = std::uint8_t __attribute__((vector_size(16)));
  const std::size_t stride = static_cast<std::size_t>(image.width) * image.channels();
  const std::size_t height = static_cast<std::size_t>(image.height);
  std::vector<std::uint8_t>& rows = image.pixels;
  rows.resize(height * (stride + 1));  // in place when the framebuffer reserved the room, as it does
  for (std::size_t y = height; y-- > 0;) {
    const std::uint8_t* row = rows.data() + y * stride;
    std::uint8_t* out = rows.data() + y * (stride + 1) + 1;
    if (y == 0) {
      std::memmove(out, row, stride);
    } else {
      const std::uint8_t* above = row - stride;
      std::size_t i = stride;
      for (; i >= 16; i -= 16) {
        Bytes r, a;
        std::memcpy(&r, row + i - 16, 16);
        std::memcpy(&a, above + i - 16, 16);
        r -= a;
        std::memcpy(out + i - 16, &r, 16);
      }
      while (i-- > 0) out[i] = static_cast<std::uint8_t>(row[i] - above[i]);
    }
    out[-1] = 2;
  }
  return write_png(image, std::move(rows), png.deflate_level);
}

}  // namespace raster
