// UTF-8 validation: an ASCII fast path eight bytes at a time (scenes are almost all ASCII), then the
// well-formed byte sequences of RFC 3629, table 3-7 of the Unicode standard.
#include "raster/utf8.h"

#include "raster/error.h"

#include <cstdint>
#include <cstring>

namespace raster {
namespace {

// Length of the well-formed sequence that starts at text[i], or 0 when it is ill-formed.
std::size_t sequence_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) return 1;
  std::size_t n;
  unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    n = 2;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3;
    if (b0 == 0xE0) lo = 0xA0;  // overlong below U+0800
    if (b0 == 0xED) hi = 0x9F;  // surrogates U+D800..DFFF
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4;
    if (b0 == 0xF0) lo = 0x90;  // overlong below U+10000
    if (b0 == 0xF4) hi = 0x8F;  // above U+10FFFF
  } else {
    return 0;  // a continuation byte on its own, C0/C1 (always overlong), F5..FF
  }
  if (text.size() - i < n) return 0;  // cut short
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  return n;
}

}  // namespace

std::size_t first_invalid_utf8(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    if (text.size() - i >= 8) {  // skip ASCII a word at a time
      std::uint64_t word;
      std::memcpy(&word, text.data() + i, 8);
      if ((word & 0x8080808080808080ull) == 0) {
        i += 8;
        continue;
      }
    }
    const std::size_t n = sequence_length(text, i);
    if (n == 0) return i;
    i += n;
  }
  return std::string_view::npos;
}

namespace {

// Why the sequence at text[i] is ill-formed, in words.
std::string why_ill_formed(std::string_view text, std::size_t i) {
  const auto b0 = static_cast<unsigned char>(text[i]);
  const auto b1 = i + 1 < text.size() ? static_cast<unsigned char>(text[i + 1]) : 0;
  if (b0 >= 0x80 && b0 <= 0xBF) return "a continuation byte with no lead byte before it";
  if (b0 == 0xC0 || b0 == 0xC1 || (b0 == 0xE0 && b1 >= 0x80 && b1 < 0xA0) ||
      (b0 == 0xF0 && b1 >= 0x80 && b1 < 0x90))
    return "an overlong encoding";
  if (b0 == 0xED && b1 >= 0xA0 && b1 <= 0xBF) return "a UTF-16 surrogate (U+D800..U+DFFF)";
  if (b0 >= 0xF8) return "a byte that never occurs in UTF-8";
  if (b0 >= 0xF5 || (b0 == 0xF4 && b1 >= 0x90 && b1 <= 0xBF)) return "beyond U+10FFFF, the last code point";
  return "a sequence cut short";
}

}  // namespace

void require_utf8(std::string_view text, const std::string& what, bool with_line) {
  const std::size_t at = first_invalid_utf8(text);
  if (at == std::string_view::npos) return;
  static constexpr char kHex[] = "0123456789ABCDEF";
  const auto b = static_cast<unsigned char>(text[at]);
  // Bytes are counted from 1 here as in the error's location (and in "line"), so the two always agree.
  std::string message = what + " is not valid UTF-8: byte " + std::to_string(at + 1) + " (0x" + kHex[b >> 4] +
                        kHex[b & 15] + ") is " + why_ill_formed(text, at) + "; send text as UTF-8";
  ErrorLocation where{"", at + 1, 0};
  if (with_line) {
    where.line = 1;
    for (std::size_t k = 0; k < at; ++k) where.line += text[k] == '\n';
  }
  throw SceneError(ErrorKind::encoding, std::move(message), std::move(where));
}

std::string escape_for_display(std::string_view text) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    const std::size_t n = sequence_length(text, i);
    if (n == 0 || b < 0x20 || b == 0x7F) {
      out += "\\x";
      out += kHex[b >> 4];
      out += kHex[b & 15];
      ++i;
    } else {
      out.append(text, i, n);
      i += n;
    }
  }
  return out;
}

}  // namespace raster
