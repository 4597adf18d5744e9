// The tokenizer's slower paths: escapes, the number grammar, skipping a value, and error messages.
#include "base/json_cursor.h"

#include "raster/utf8.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <vector>

namespace raster {
namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

void append_utf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6)), out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12)), out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18)), out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F)), out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

}  // namespace

void JsonCursor::fail_at(const char* at, std::string_view what) const {
  std::string message = "malformed JSON: " + std::string(what);
  if (at == end_) {
    if (what.find("end of") == std::string_view::npos) message += ", got the end of the text";
  } else {
    const unsigned char c = static_cast<unsigned char>(*at);
    // The byte itself when printable; a multi-byte character or a control byte by its code.
    char shown[16];
    if (c > ' ' && c < 0x7F)
      std::snprintf(shown, sizeof shown, "'%c'", c);
    else
      std::snprintf(shown, sizeof shown, "byte 0x%02X", c);
    message += std::string(", got ") + shown;
  }
  throw SceneError(ErrorKind::syntax, message,
                   ErrorLocation{"", static_cast<std::size_t>(at - begin_) + 1, 0});
}

void JsonCursor::too_deep() const {
  throw SceneError(ErrorKind::syntax, "JSON nested deeper than " + std::to_string(max_depth_) + " levels",
                   ErrorLocation{"", offset(), 0});
}

void JsonCursor::require_utf8(const char* from, const char* to) const {
  if (first_invalid_utf8(std::string_view(from, static_cast<std::size_t>(to - from))) ==
      std::string_view::npos)
    return;
  // The whole text's first bad byte: none is before this string (every earlier string was checked, and a
  // byte above 0x7F outside a string is a syntax error), so this names the byte in this one.
  raster::require_utf8(std::string_view(begin_, static_cast<std::size_t>(end_ - begin_)), "the scene");
}

std::string_view JsonCursor::escaped_string(const char* start) {
  scratch_.assign(start, p_);
  auto hex4 = [&](const char* at) {
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k) {
      const int d = at + k < end_ ? hex_value(at[k]) : -1;
      if (d < 0) fail_at(at + k, "expected four hex digits after \\u");
      v = v * 16 + static_cast<std::uint32_t>(d);
    }
    return v;
  };
  while (true) {
    if (p_ == end_) fail("expected '\"' to close the string");
    const char c = *p_;
    if (c == '"') return require_utf8(start, p_), ++p_, scratch_;
    if (static_cast<unsigned char>(c) < 0x20) fail("a control character must be escaped in a string");
    if (c != '\\') {
      scratch_ += c, ++p_;
      continue;
    }
    if (++p_ == end_) fail("expected an escape after '\\'");
    switch (*p_++) {
      case '"':
        scratch_ += '"';
        break;
      case '\\':
        scratch_ += '\\';
        break;
      case '/':
        scratch_ += '/';
        break;
      case 'b':
        scratch_ += '\b';
        break;
      case 'f':
        scratch_ += '\f';
        break;
      case 'n':
        scratch_ += '\n';
        break;
      case 'r':
        scratch_ += '\r';
        break;
      case 't':
        scratch_ += '\t';
        break;
      case 'u': {
        std::uint32_t cp = hex4(p_);
        p_ += 4;
        if (cp >= 0xDC00 && cp <= 0xDFFF)
          fail_at(p_ - 6, "a low surrogate \\uDC00..\\uDFFF without a high one");
        if (cp >= 0xD800 && cp <= 0xDBFF) {  // a pair: \uD8xx\uDCxx is one code point above U+FFFF
          if (end_ - p_ < 2 || p_[0] != '\\' || p_[1] != 'u')
            fail("expected \\uDC00..\\uDFFF after a high surrogate");
          const std::uint32_t low = hex4(p_ + 2);
          if (low < 0xDC00 || low > 0xDFFF) fail("expected \\uDC00..\\uDFFF after a high surrogate");
          p_ += 6;
          cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
        }
        append_utf8(scratch_, cp);
        break;
      }
      default:
        fail_at(p_ - 1, "unknown escape");
    }
  }
}

std::size_t JsonCursor::count(std::string_view text, char c) {
  using Bytes = std::uint8_t __attribute__((vector_size(16)));  // GCC vector extensions: SSE2 on x86-64
  std::size_t total = 0, i = 0;
  const std::size_t size = text.size();
  while (size - i >= 16) {
    Bytes hits = {};  // per lane, up to 255 blocks before it could wrap
    const std::size_t end = i + std::min<std::size_t>((size - i) / 16, 255) * 16;
    for (; i < end; i += 16) {
      Bytes block;
      std::memcpy(&block, text.data() + i, 16);
      hits -= reinterpret_cast<Bytes>(block == static_cast<std::uint8_t>(c));  // a match is -1
    }
    for (int k = 0; k < 16; ++k) total += hits[k];
  }
  for (; i < size; ++i) total += text[i] == c;
  return total;
}

std::size_t JsonCursor::flat_array_size() {
  space();
  if (p_ == end_ || *p_ != '[') return 0;
  const char* close =
      static_cast<const char*>(std::memchr(p_ + 1, ']', static_cast<std::size_t>(end_ - p_ - 1)));
  if (!close) return 0;
  const std::string_view body(p_ + 1, static_cast<std::size_t>(close - p_ - 1));
  for (const char c :
       {'[', '{', '"'})  // nested or not numbers: no estimate (memchr: wide, unlike find_first_of)
    if (std::memchr(body.data(), c, body.size())) return 0;
  return body.find_first_not_of(" \t\r\n") == std::string_view::npos ? 0 : count(body, ',') + 1;
}

bool JsonCursor::overflows(const char* q) const {
  // The decimal magnitude is the integer digits after leading zeros, or minus the fraction's leading
  // zeros, plus the exponent; out of range happens only hundreds of powers of ten away from 0.
  if (*q == '-') ++q;
  long magnitude = 0;
  bool nonzero = false;
  for (; q < p_ && is_digit(*q); ++q) nonzero = nonzero || *q != '0', magnitude += nonzero;
  if (q < p_ && *q == '.')
    for (++q; q < p_ && is_digit(*q); ++q)
      if (!nonzero) nonzero = *q != '0', magnitude -= !nonzero;
  long exponent = 0;
  if (q < p_ && (*q == 'e' || *q == 'E')) {
    const bool negative = *++q == '-';
    if (*q == '-' || *q == '+') ++q;
    for (; q < p_ && is_digit(*q); ++q) exponent = std::min(exponent * 10 + (*q - '0'), 100'000'000L);
    if (negative) exponent = -exponent;
  }
  return magnitude + exponent > 0;
}

std::string_view JsonCursor::skip() {
  const char* start = (peek(), p_);
  // Without recursion, so the stack stays flat however deep a library caller lets documents nest: one
  // entry per open container, true for an object (whose next member starts with a key).
  std::vector<bool> open;
  while (true) {
    bool opened = false;
    switch (peek()) {
      case Kind::object:
        if ((opened = object_begin())) open.push_back(true), key();
        break;
      case Kind::array:
        if ((opened = array_begin())) open.push_back(false);
        break;
      case Kind::string:
        string_body();
        break;
      case Kind::number:
        number();
        break;
      case Kind::boolean:
        boolean();
        break;
      case Kind::null:
        if (!literal("null")) fail("expected a value");
        break;
    }
    if (opened) continue;  // its first element is next
    // A value ended: close the containers it ends, until one has another element.
    while (!open.empty()) {
      if (open.back() ? object_next() : array_next()) {
        if (open.back()) key();
        break;
      }
      open.pop_back();
    }
    if (open.empty()) return {start, static_cast<std::size_t>(p_ - start)};
  }
}

}  // namespace raster
