// Texture files -> Texture: PNG and JPEG through stb_image, compiled for those two formats only, and the
// size read from the header and checked before a single texel is decoded (a 20-byte PNG can claim
// 100,000 x 100,000 pixels: that is a limit error, never a 40 GB allocation).
#include <algorithm>
#include <cstring>
#include <memory>
#include <string>

#include "raster/scene.h"

#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO      // from memory only: a texture never names a file on this machine
#define STBI_NO_LINEAR     // no float (HDR) paths
#define STBI_NO_HDR
#define STBI_MAX_DIMENSIONS 16384  // = kMaxTextureSide: stb_image refuses larger sides by itself, too
#define STB_IMAGE_STATIC           // private to this file: no clash with another copy of stb_image
#define STB_IMAGE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace raster {
namespace {

static_assert(STBI_MAX_DIMENSIONS == kMaxTextureSide);

[[noreturn]] void texture_error(ErrorKind kind, std::string_view name, const std::string& message) {
  throw SceneError(kind, "texture \"" + std::string(name) + "\": " + message);
}

const char* format_of(std::string_view bytes) {
  if (bytes.size() >= 8 && std::memcmp(bytes.data(), "\x89PNG\r\n\x1a\n", 8) == 0) return "png";
  if (bytes.size() >= 3 && std::memcmp(bytes.data(), "\xff\xd8\xff", 3) == 0) return "jpeg";
  return nullptr;
}

// The size the file's header claims, read here rather than from stb_image, whose stbi_info reports only
// the last format it tried when a header is refused ("unknown image type" for a PNG too large to load).
// PNG: the IHDR, always the first chunk. JPEG: the first start-of-frame marker. False when not found.
bool claimed_size(std::string_view b, std::int64_t& w, std::int64_t& h) {
  auto be = [&](std::size_t at, int n) {
    std::int64_t v = 0;
    for (int k = 0; k < n; ++k) v = v << 8 | static_cast<std::uint8_t>(b[at + k]);
    return v;
  };
  if (b[0] != '\xff') {  // PNG
    if (b.size() < 24 || b.substr(12, 4) != "IHDR") return false;
    w = be(16, 4), h = be(20, 4);
    return true;
  }
  for (std::size_t at = 2; at + 4 <= b.size();) {  // JPEG: segments FF <marker> <16-bit length> ...
    if (static_cast<std::uint8_t>(b[at]) != 0xff) return false;
    const auto marker = static_cast<std::uint8_t>(b[at + 1]);
    if (marker == 0xff) {  // fill byte
      ++at;
      continue;
    }
    const bool sof = marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
    if (sof) {
      if (at + 9 > b.size()) return false;
      h = be(at + 5, 2), w = be(at + 7, 2);
      return true;
    }
    if (marker == 0xd9 || marker == 0xda) return false;  // end of image, or scan data before any frame
    at += 2 + static_cast<std::size_t>(be(at + 2, 2));
  }
  return false;
}

// Every chunk up to IEND lies whole inside the file. stb_image sizes its buffer for the compressed data
// from the lengths the IDAT chunks declare before it reads them, so a 336-byte file declaring a 2 GB
// IDAT made it allocate 2 GB (found by texture_fuzzer). With this check its buffer stays within twice the
// file, which the body limit bounds. Empty file or trailing bytes after IEND are left to the decoder.
void check_png_chunks(std::string_view b, std::string_view name) {
  std::size_t at = 8;
  while (at < b.size()) {
    if (b.size() - at < 12) texture_error(ErrorKind::model, name, "truncated: a PNG chunk is cut short");
    std::uint64_t n = 0;
    for (int k = 0; k < 4; ++k) n = n << 8 | static_cast<std::uint8_t>(b[at + k]);
    const std::string type(b.substr(at + 4, 4));
    if (n > b.size() - at - 12)
      texture_error(ErrorKind::model, name,
                    "truncated or corrupt: PNG chunk \"" + type + "\" at byte " +
                        std::to_string(at) + " declares " + std::to_string(n) + " bytes; the file has " +
                        std::to_string(b.size() - at - 12) + " left");
    at += 12 + n;
    if (type == "IEND") break;
  }
}

// The PNG without its empty IDAT chunks (legal, and carrying nothing), or `b` itself when it has none:
// stb_image reads a first IDAT of length 0 with memcpy(NULL, src, 0), undefined behaviour that UBSan
// reports (found by texture_fuzzer). Chunks are walked only while their lengths fit; the rest is left to
// the decoder to judge.
std::string_view without_empty_idat(std::string_view b, std::string& copy) {
  // Each chunk: 4-byte length, 4-byte type, data, 4-byte CRC. Calls `chunk(at, bytes, empty_idat)` for each
  // whose header fits, `bytes` clipped to the file (a last chunk may lack its CRC, or more).
  auto walk = [&](auto&& chunk) {
    std::size_t at = 8;
    while (at + 8 <= b.size()) {
      std::uint64_t n = 0;
      for (int k = 0; k < 4; ++k) n = n << 8 | static_cast<std::uint8_t>(b[at + k]);
      const bool empty_idat = n == 0 && b.substr(at + 4, 4) == "IDAT";
      const std::size_t bytes = static_cast<std::size_t>(std::min<std::uint64_t>(12 + n, b.size() - at));
      chunk(at, bytes, empty_idat);
      at += bytes;
    }
    return at;
  };
  bool any = false;
  walk([&](std::size_t, std::size_t, bool empty_idat) { any |= empty_idat; });
  if (!any) return b;
  copy.assign(b.substr(0, 8));
  const std::size_t end = walk([&](std::size_t at, std::size_t bytes, bool empty_idat) {
    if (!empty_idat) copy.append(b.substr(at, bytes));
  });
  copy.append(b.substr(std::min(end, b.size())));  // a tail shorter than a chunk header
  return copy;
}

}  // namespace

Texture decode_texture(std::string_view bytes, std::string_view name, std::int64_t texel_budget) {
  if (!format_of(bytes))
    texture_error(ErrorKind::model, name,
                  bytes.empty() ? "the file is empty" : "not a PNG or JPEG file (textures must be PNG or JPEG)");
  if (bytes.size() > static_cast<std::size_t>(INT32_MAX))
    texture_error(ErrorKind::limit, name, "the file is larger than 2 GiB");
  std::int64_t w = 0, h = 0;
  if (!claimed_size(bytes, w, h)) texture_error(ErrorKind::model, name, "its header cannot be read");
  if (w < 1 || h < 1) texture_error(ErrorKind::model, name, "the image has no pixels");
  const std::string size = std::to_string(w) + "x" + std::to_string(h);
  if (w > kMaxTextureSide || h > kMaxTextureSide)
    texture_error(ErrorKind::limit, name,
                  size + " pixels: a side exceeds the limit of " + std::to_string(kMaxTextureSide));
  if (w * h > texel_budget)
    texture_error(ErrorKind::limit, name,
                  size + " pixels exceed what is left of the scene's texture limit (" +
                      std::to_string(std::max<std::int64_t>(texel_budget, 0)) + " pixels)");

  const bool png = format_of(bytes)[0] == 'p';
  if (png) check_png_chunks(bytes, name);
  std::string copy;
  const std::string_view decodable = png ? without_empty_idat(bytes, copy) : bytes;
  int dw = 0, dh = 0, channels = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(decodable.data()), static_cast<int>(decodable.size()),
                            &dw, &dh, &channels, 4),
                                                   stbi_image_free);
  if (!pixels) texture_error(ErrorKind::model, name, std::string("cannot be decoded: ") + stbi_failure_reason());
  if (dw != w || dh != h)  // the header said one size and the decoder made another: not trusted
    texture_error(ErrorKind::model, name, "the decoded size differs from the header's");
  Texture t;
  t.width = dw, t.height = dh;
  t.name = std::string(name);
  t.rgba.assign(pixels.get(), pixels.get() + std::size_t(dw) * std::size_t(dh) * 4);
  return t;
}

}  // namespace raster
