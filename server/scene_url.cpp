#include "scene_url.h"

#include <zlib.h>

#include <array>
#include <cstdint>
#include <new>

namespace rasterd {
namespace {

// Value of each base64url character, or -1.
constexpr std::array<std::int8_t, 256> kBase64Url = [] {
  std::array<std::int8_t, 256> t{};
  t.fill(-1);
  const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
  for (int i = 0; i < 64; ++i) t[static_cast<unsigned char>(alphabet[i])] = static_cast<std::int8_t>(i);
  return t;
}();

[[noreturn]] void bad(const std::string& message) {
  throw SceneUrlError(400, "query parameter \"scene\": " + message);
}

std::string decode_base64url(std::string_view text) {
  std::size_t end = text.size();
  while (end > 0 && text[end - 1] == '=' && text.size() - end < 2) --end;  // at most two '='
  if (text.empty()) bad("empty; expected the base64url of a scene");
  std::string out;
  out.reserve(end / 4 * 3 + 2);
  std::uint32_t bits = 0;
  int count = 0;
  for (std::size_t i = 0; i < end; ++i) {
    const int v = kBase64Url[static_cast<unsigned char>(text[i])];
    if (v < 0) {
      std::string message = "character " + std::to_string(i + 1) + " is not base64url (A-Z a-z 0-9 - _)";
      if (text[i] == '+' || text[i] == '/' || text[i] == ' ')  // '+' arrives as a space once URL-decoded
        message += "; use the URL-safe alphabet: '-' for '+' and '_' for '/'";
      bad(message);
    }
    bits = bits << 6 | static_cast<std::uint32_t>(v);
    if (++count == 4) {
      out += static_cast<char>(bits >> 16), out += static_cast<char>(bits >> 8),
          out += static_cast<char>(bits);
      bits = 0, count = 0;
    }
  }
  if (count == 1) bad("its length is not that of any base64url text (one character too many or too few)");
  if (count == 2) out += static_cast<char>(bits >> 4);
  if (count == 3) out += static_cast<char>(bits >> 10), out += static_cast<char>(bits >> 2);
  return out;
}

// What wraps the deflate stream, as zlib's windowBits says it: -15 none (CompressionStream('deflate-raw')),
// 15 a zlib header and Adler-32 trailer (RFC 1950: pako.deflate, Python's zlib.compress, Kroki's own
// examples), 31 gzip (RFC 1952).
int window_bits_of(const std::string& bytes) {
  if (bytes.size() >= 2) {
    const auto b0 = static_cast<unsigned char>(bytes[0]), b1 = static_cast<unsigned char>(bytes[1]);
    if (b0 == 0x1F && b1 == 0x8B) return 31;
    if ((b0 & 0x0F) == 8 && (b0 >> 4) <= 7 && (b0 << 8 | b1) % 31 == 0) return 15;
  }
  return -15;
}

std::string inflate_text(const std::string& compressed, std::size_t max_bytes, int window_bits) {
  const char* reading = window_bits == 15 ? "zlib" : window_bits == 31 ? "gzip" : "raw deflate";
  z_stream zs{};
  if (inflateInit2(&zs, window_bits) != Z_OK) throw std::bad_alloc();
  struct End {
    z_stream& zs;
    ~End() { inflateEnd(&zs); }
  } end{zs};
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
  zs.avail_in = static_cast<uInt>(compressed.size());  // a URL's worth: far below 4 GiB
  std::string out;
  std::array<char, 1 << 16> chunk;
  for (;;) {
    zs.next_out = reinterpret_cast<Bytef*>(chunk.data());
    zs.avail_out = static_cast<uInt>(chunk.size());
    const int rc = inflate(&zs, Z_NO_FLUSH);
    const std::size_t produced = chunk.size() - zs.avail_out;
    // Checked before appending: the output never holds more than the limit plus nothing.
    if (out.size() + produced > max_bytes)
      throw SceneUrlError(413, "query parameter \"scene\" inflates to more than the limit of " +
                                   std::to_string(max_bytes) + " bytes");
    out.append(chunk.data(), produced);
    if (rc == Z_STREAM_END) break;
    if (rc == Z_MEM_ERROR) throw std::bad_alloc();
    if (rc == Z_DATA_ERROR || rc == Z_NEED_DICT)
      bad("the decoded bytes do not start with '{' (plain JSON) and are not a deflate stream, raw or "
          "zlib-wrapped (read as " +
          std::string(reading) + ": " + (zs.msg ? zs.msg : "invalid data") + ")");
    if (rc == Z_BUF_ERROR || (zs.avail_in == 0 && produced == 0))
      bad("the deflate stream (read as " + std::string(reading) + ") ends early (truncated URL?)");
  }
  if (zs.avail_in != 0)
    bad(std::to_string(zs.avail_in) + " bytes follow the end of the deflate stream (read as " + reading +
        ")");
  return out;
}

}  // namespace

std::string decode_scene_param(std::string_view param, std::size_t max_bytes) {
  std::string decoded = decode_base64url(param);
  if (!decoded.empty() && decoded[0] == '{') {
    if (decoded.size() > max_bytes)
      throw SceneUrlError(
          413, "query parameter \"scene\" is more than the limit of " + std::to_string(max_bytes) + " bytes");
    return decoded;
  }
  const int window_bits = window_bits_of(decoded);
  if (window_bits == -15) return inflate_text(decoded, max_bytes, -15);
  try {
    return inflate_text(decoded, max_bytes, window_bits);
  } catch (const SceneUrlError& wrapped) {
    // Two bytes that happen to look like a zlib header can begin a raw stream too: that reading may work.
    if (wrapped.status() == 413) throw;
    try {
      return inflate_text(decoded, max_bytes, -15);
    } catch (const SceneUrlError&) {
      throw wrapped;  // the error of what the header announced
    }
  }
}

}  // namespace rasterd
