// Texture files -> Texture: PNG and JPEG through stb_image, compiled for those two formats only, and the
// size read from the header and checked before a single texel is decoded (a 20-byte PNG can claim
// 100,000 x 100,000 pixels: that is a limit error, never a 40 GB allocation).
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "raster/model.h"

#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO   // from memory only: a texture never names a file on this machine
#define STBI_NO_LINEAR  // no float (HDR) paths
#define STBI_NO_HDR
#define STBI_MAX_DIMENSIONS 16384  // = kMaxTextureSide: stb_image refuses larger sides by itself, too
#define STB_IMAGE_STATIC           // private to this file: no clash with another copy of stb_image
// stb_image's allocations go through here. Each is zeroed: stb_image 2.27 (Debian 12's) mallocs its JPEG
// decoder state and leaves the Huffman and quantisation tables of a scan that no DHT or DQT defined
// uninitialised: decoding then indexed from garbage (stb issue #1289, fixed upstream in 2.28) and the same
// file could decode differently twice. Zeroed tables decode in bounds and always to the same pixels.
// Each is also capped by the decode in progress: stb_image inflates PNG data into a buffer it doubles for as
// long as the data goes on, and accepts more data than the header's size needs, so a 1.4 MB PNG of deflated
// zeros behind a 1x1 header took 1.4 GB of memory for a 1x1 texture (peak RSS, measured on stb_image alone).
// Its allocator hooks take no context:
// the cap is a thread_local that StbDecode sets for the length of one stbi_load_from_memory call on this
// thread, and which is unlimited otherwise.
namespace {
thread_local std::size_t t_stb_cap = SIZE_MAX;  ///< bytes, the largest allocation the decode may make
thread_local bool t_stb_capped = false;         ///< whether the decode asked for more than that
void* stb_malloc(std::size_t bytes) {
  if (bytes > t_stb_cap) return t_stb_capped = true, nullptr;
  return std::calloc(1, bytes);
}
void* stb_realloc(void* p, std::size_t bytes) {
  if (bytes > t_stb_cap) return t_stb_capped = true, nullptr;
  return std::realloc(p, bytes);
}
}  // namespace
#define STBI_MALLOC(size) stb_malloc(size)
#define STBI_REALLOC(p, size) stb_realloc(p, size)
#define STBI_FREE(p) std::free(p)
// stb_image 2.27's JPEG bit reader takes more bits than a scan holds when a marker cuts it short (a corrupt
// file): its count of buffered bits goes negative, and the next refill shifts by 32 or more, which is
// undefined behaviour (stb issue #1293, found here by texture_fuzzer; 2.28 reads zeros there instead). Every
// read calls stbi__grow_buffer_unsafe when the count is low, so the calls, and only the calls, are sent to
// stb_grow_checked below, which empties a negative count first: what follows the cut reads as zeros, as in
// 2.28, and as stb_image 2.27 itself reads past the end of a file. The macro tells the definition
// (`stbi__grow_buffer_unsafe(stbi__jpeg *j)`, whose argument starts with the type) from a call (`(j)`):
// pasting gives the probe RASTERD_STB_PROBE_stbi__jpeg, a macro with an extra comma, only for the definition,
// which keeps stb's body under the name stb_grow_unchecked.
template <typename Jpeg>
static void stb_grow_checked(Jpeg* j);
#define RASTERD_STB_PROBE_stbi__jpeg ~, stb_grow_unchecked,
#define RASTERD_STB_SECOND(a, b, ...) b
#define RASTERD_STB_PICK(...) RASTERD_STB_SECOND(__VA_ARGS__)
#define RASTERD_STB_PASTE(a, b) a##b
#define stbi__grow_buffer_unsafe(x) \
  RASTERD_STB_PICK(RASTERD_STB_PASTE(RASTERD_STB_PROBE_, x), stb_grow_checked, ~)(x)
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
#undef stbi__grow_buffer_unsafe

template <typename Jpeg>
static void stb_grow_checked(Jpeg* j) {
  if (j->code_bits < 0) j->code_bits = 0, j->code_buffer = 0;  // past a cut: nothing buffered is data
  stb_grow_unchecked(j);
}

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
                    "truncated or corrupt: PNG chunk \"" + type + "\" at byte " + std::to_string(at) +
                        " declares " + std::to_string(n) + " bytes; the file has " +
                        std::to_string(b.size() - at - 12) + " left");
    at += 12 + n;
    if (type == "IEND") break;
  }
}

// The scan header (SOS) at `at` (its length field): each component's DC table must be defined if the scan
// decodes DC coefficients with one (a baseline scan, or a progressive first DC pass: Ss = 0, Ah = 0), its AC
// table if it decodes AC coefficients (baseline, or Se > 0).
void check_first_scan(std::string_view b, std::size_t at, bool progressive, const bool (&defined)[2][4],
                      std::string_view name) {
  auto byte = [&](std::size_t k) -> std::size_t {
    return k < b.size() ? static_cast<std::uint8_t>(b[k]) : 0;
  };
  const std::size_t components = byte(at + 2);
  if (components < 1 || components > 4) return;      // stb_image refuses it ("bad SOS component count")
  const std::size_t tail = at + 3 + 2 * components;  // Ss, Se, Ah/Al
  const bool uses_dc = !progressive || (byte(tail) == 0 && byte(tail + 2) >> 4 == 0);
  const bool uses_ac = !progressive || byte(tail + 1) > 0;
  for (std::size_t c = 0; c < components; ++c) {
    const std::size_t tables = byte(at + 4 + 2 * c), dc = tables >> 4, ac = tables & 15;
    if (dc > 3 || ac > 3) return;  // stb_image refuses it ("bad DC huff" / "bad AC huff")
    const char* missing = uses_dc && !defined[0][dc] ? "DC" : uses_ac && !defined[1][ac] ? "AC" : nullptr;
    if (missing)
      texture_error(ErrorKind::model, name,
                    std::string("corrupt JPEG: the scan at byte ") + std::to_string(at) + " uses " + missing +
                        " Huffman table " + std::to_string(missing[0] == 'D' ? dc : ac) +
                        ", which no table segment (DHT) before it defines");
  }
}

// JPEG: no Huffman table stb_image reads may hold more than 256 codes. stb_image 2.27 builds a table from its
// 16 code counts into 257-entry arrays without checking their sum (up to 16 x 255), writing past them, and
// then reads that many values into a 256-entry array (stb issues #1289 and #1291, fixed upstream in 2.28;
// found here by texture_fuzzer). A DHT segment is read as stb_image reads it: a 16-bit length, then tables
// of a class/id byte, 16 counts and their values while the length lasts; past the file's end stb_image reads
// zeros, which make no codes. Up to the first scan the segments are walked as stb_image walks them (stray
// bytes before the frame header skipped as it skips them). From there on it finds markers where its entropy
// decoder stops, which only decoding tells, so every FF C4 pair is taken for a DHT it might read; a valid
// file never has one inside scan data (an FF there is followed by 00 or a restart marker).
//
// The first scan's tables are known exactly: one it selects that no DHT before it defined is refused
// (stb_image would decode it from zeroed tables, as flat grey). Later scans (progressive files) are left to
// the zeroed allocation above.
void check_jpeg_huffman_tables(std::string_view b, std::string_view name) {
  auto byte = [&](std::size_t at) -> std::size_t {
    return at < b.size() ? static_cast<std::uint8_t>(b[at]) : 0;
  };
  bool defined[2][4] = {};                // [DC, AC][table id]: by the DHTs read so far
  auto check_dht = [&](std::size_t at) {  // `at`: the segment's length field
    std::int64_t left = static_cast<std::int64_t>(byte(at) << 8 | byte(at + 1)) - 2;
    for (at += 2; left > 0 && at < b.size();) {
      const std::size_t q = byte(at);
      if (q >> 4 > 1 || (q & 15) > 3) return;  // stb_image refuses it ("bad DHT header") and stops
      std::size_t codes = 0;
      for (int i = 1; i <= 16; ++i) codes += byte(at + i);
      if (codes > 256)
        texture_error(ErrorKind::model, name,
                      "corrupt JPEG: a Huffman table (DHT) at byte " + std::to_string(at) + " declares " +
                          std::to_string(codes) + " codes; at most 256 exist");
      defined[q >> 4][q & 15] = true;
      at += 17 + codes, left -= static_cast<std::int64_t>(17 + codes);
    }
  };
  std::size_t at = 2;  // after SOI
  bool frame = false, progressive = false;
  while (at < b.size()) {
    if (byte(at) != 0xff) {
      if (frame) break;  // stb_image refuses the file here; the rest is checked below all the same
      ++at;
      continue;
    }
    while (at < b.size() && byte(at) == 0xff) ++at;  // fill bytes
    if (at >= b.size()) return;
    const std::size_t marker = byte(at++);
    if (marker == 0xd9) return;  // EOI
    const bool known = marker == 0xc4 || marker == 0xdb || marker == 0xdd || marker == 0xfe ||
                       (marker >= 0xe0 && marker <= 0xef) || (marker >= 0xc0 && marker <= 0xc2);
    if (marker == 0xda && frame) check_first_scan(b, at, progressive, defined, name);
    if (marker == 0xda || !known) break;  // the first scan, or a marker stb_image refuses
    if (marker == 0xc4) check_dht(at);
    frame |= marker >= 0xc0 && marker <= 0xc2;
    progressive |= marker == 0xc2;
    at += byte(at) << 8 | byte(at + 1);  // each of these is read, or skipped, by its length
  }
  for (std::size_t k = at > 0 ? at - 1 : 0; k + 1 < b.size(); ++k)
    if (byte(k) == 0xff && byte(k + 1) == 0xc4) check_dht(k + 2);
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

// The cap on each of stb_image's allocations while it decodes one file of `file_bytes` whose header says
// w x h: no buffer a valid file needs is larger than twice the file (its compressed data gathered, doubling)
// or twice its raw size, taken as 8 bytes a pixel over the image grown by 32 each way (PNG rows of 16-bit
// RGBA and their filter bytes, doubling once for interlaced files; JPEG planes padded to whole 32 px MCUs),
// plus room for small tables. So what one texture may allocate follows from the size its header claims, which
// is checked against the scene's texel limit, and from the body limit, whatever its data says.
class StbDecode {
 public:
  StbDecode(std::size_t file_bytes, std::int64_t w, std::int64_t h)
      : cap_(2 * std::max(file_bytes, static_cast<std::size_t>((w + 32) * (h + 32) * 8)) +
             (std::size_t{1} << 20)) {
    t_stb_cap = cap_, t_stb_capped = false;
  }
  ~StbDecode() { t_stb_cap = SIZE_MAX, t_stb_capped = false; }
  StbDecode(const StbDecode&) = delete;
  StbDecode& operator=(const StbDecode&) = delete;
  bool capped() const { return t_stb_capped; }
  std::size_t cap() const { return cap_; }

 private:
  std::size_t cap_;  ///< bytes
};

}  // namespace

Texture decode_texture(std::string_view bytes, std::string_view name, std::int64_t texel_budget) {
  if (!format_of(bytes))
    texture_error(
        ErrorKind::model, name,
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
  if (png)
    check_png_chunks(bytes, name);
  else
    check_jpeg_huffman_tables(bytes, name);
  std::string copy;
  const std::string_view decodable = png ? without_empty_idat(bytes, copy) : bytes;
  int dw = 0, dh = 0, channels = 0;
  StbDecode bound(decodable.size(), w, h);
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(decodable.data()),
                            static_cast<int>(decodable.size()), &dw, &dh, &channels, 4),
      stbi_image_free);
  if (!pixels && bound.capped())
    texture_error(ErrorKind::model, name,
                  "corrupt: its compressed data inflates to more than a " + size +
                      " image holds (the decoder stopped at " + std::to_string(bound.cap()) + " bytes)");
  if (!pixels)
    texture_error(ErrorKind::model, name, std::string("cannot be decoded: ") + stbi_failure_reason());
  if (dw != w || dh != h)  // the header said one size and the decoder made another: not trusted
    texture_error(ErrorKind::model, name, "the decoded size differs from the header's");
  Texture t;
  t.width = dw, t.height = dh;
  t.name = std::string(name);
  t.rgba.assign(pixels.get(), pixels.get() + std::size_t(dw) * std::size_t(dh) * 4);
  return t;
}

}  // namespace raster
