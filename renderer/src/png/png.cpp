// PNG encoding: the Up row filter, ISA-L's deflate (igzip) and CRC, written straight into one buffer.
//
// A PNG is a signature and three chunks here (IHDR, one IDAT, IEND), so the container is a few lines; the
// cost is all in filtering and compressing. Both were chosen by measurement (bench/png_sweep, run by
// make bench into docs/performance.md): on the benchmark renders igzip level 1 compresses the Up-filtered
// rows in 10.5 / 6.5 / 2.8 ms where libdeflate's fastest level takes 28 / 16 / 12 ms, for files 2-12%
// larger than libdeflate's and 11-22% smaller than stb_image_write's; level 0 saves at most a tenth of the
// time and its small-scene file exceeds stb's. (Before, stb_image_write wrote the file with libdeflate hooked
// in: its bytewise CRC and copies took a sixth of the encode, and the filter and level reached it through
// process-wide settings.)
#include "raster/png.h"

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <isa-l/crc.h>

#include "png/deflate.h"

namespace raster {
namespace {

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
  const std::uint32_t crc = crc32_gzip_refl(0, out.data() + at + 4, length + 4);  // PNG's CRC-32
  put_u32(out.data() + at + 8 + length, crc);
  return at + 12 + length;
}

// The PNG of filtered rows (a filter byte, then the row, per row). The rows are released before the file
// is assembled, so at most the rows and the compressed data exist at once.
std::vector<std::uint8_t> write_png(const Image& image, std::vector<std::uint8_t>&& filtered,
                                    const PngPlan& png) {
  const auto [compressed, size] = deflate::zlib_compress(filtered, png.deflate_level);
  std::vector<std::uint8_t>().swap(filtered);

  static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  constexpr std::size_t kIhdr = 13;
  std::vector<std::uint8_t> out(8 + (12 + kIhdr) + (12 + size) + 12);
  std::memcpy(out.data(), kSignature, 8);
  std::uint8_t* ihdr = out.data() + 8 + 8;
  put_u32(ihdr, static_cast<std::uint32_t>(image.width));
  put_u32(ihdr + 4, static_cast<std::uint32_t>(image.height));
  ihdr[8] = 8;                                          // bits per channel
  ihdr[9] = static_cast<std::uint8_t>(png.color_type);  // the plan's choice
  ihdr[10] = ihdr[11] = ihdr[12] = 0;                   // deflate, adaptive filtering, no interlace
  std::size_t at = finish_chunk(out, 8, "IHDR", kIhdr);
  std::memcpy(out.data() + at + 8, compressed.get(), size);
  at = finish_chunk(out, at, "IDAT", size);
  finish_chunk(out, at, "IEND", 0);
  return out;
}

// A plan made for another pixel format would write pixels under the wrong colour type: refused.
void check_plan(const Image& image, const PngPlan& png) {
  if (png.color_type != png_plan_for(image.format).color_type)
    throw std::invalid_argument("PNG colour type " + std::to_string(png.color_type) + " does not fit a " +
                                std::to_string(image.channels()) + "-channel image");
}

}  // namespace

void prepare_png_encoders(int encodes_at_once, const PngPlan& png) {
  deflate::prepare(encodes_at_once, png.deflate_level);
}

std::size_t kept_png_encoders(int deflate_level) {
  return deflate::kept(deflate_level);
}

std::vector<std::uint8_t> encode_png(const Image& image) {
  return encode_png(image, png_plan_for(image.format));
}

std::vector<std::uint8_t> encode_png(Image&& image) {
  const PngPlan png = png_plan_for(image.format);
  return encode_png(std::move(image), png);
}

std::vector<std::uint8_t> encode_png(const Image& image, const PngPlan& png) {
  check_plan(image, png);
  // Filter "Up" on every row (the first has a row of zeros above it, so its bytes go as they are): one
  // fixed filter instead of trying all five per row. In bench/png_sweep it gives the smallest grid file
  // by 19% and is within 1-6% of "Sub" on the other scenes; "None" is larger everywhere.
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
  return write_png(image, std::move(filtered), png);
}

std::vector<std::uint8_t> encode_png(Image&& image, const PngPlan& png) {
  check_plan(image, png);
  // The same rows, filtered where they lie: row y moves y + 1 bytes further into the buffer to make room
  // for the filter bytes, so rows go bottom to top (the row above is still unfiltered when a row needs it),
  // and within a row 16 bytes are read before they are written, from the end down, so no unread byte is
  // overwritten.
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
  return write_png(image, std::move(rows), png);
}

}  // namespace raster
