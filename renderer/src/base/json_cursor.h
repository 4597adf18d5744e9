// A validating pull tokenizer over JSON text (RFC 8259): the scene reader asks for the value it expects
// next and the cursor either gives it or throws SceneError(syntax) with the 1-based byte offset of the
// first byte that cannot belong to a well-formed document.
//
// Why our own and not RapidJSON's SAX Reader: pulled values let a descriptor's reader read its field
// where it stands (a point straight into the scene's array) instead of a state machine driven by events,
// and it measured 3.3x faster on the bench scenes, each checking all the text and converting every number
// (docs/performance.md, the tokenize/ rows). UTF-8 is checked in each string as it is read (bytes above 0x7F
// are JSON nowhere else); escapes are checked too, lone surrogates included.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "raster/error.h"

namespace raster {

// A JSON pointer kept as parent links on the stack and spelled out only for an error, with the byte where
// the value it names starts. Keys must outlive the pointer (views of the text, or held by the caller).
class JsonPointer {
 public:
  JsonPointer() = default;  // the document root
  JsonPointer(const JsonPointer& parent, std::string_view key, std::size_t byte)
      : parent_(&parent), key_(key), byte_(byte) {}
  JsonPointer(const JsonPointer& parent, std::size_t index, std::size_t byte)
      : parent_(&parent), index_(index), byte_(byte), is_index_(true) {}
  std::size_t byte() const { return byte_; }
  /// Itself, whatever byte is asked for: a pointer made already serves where a maker of one is taken.
  const JsonPointer& operator()(std::size_t) const { return *this; }
  std::string str() const {
    if (!parent_) return "";
    std::string out = parent_->str() + "/";
    if (is_index_) return out + std::to_string(index_);
    for (char c : key_) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);  // RFC 6901
    return out;
  }

 private:
  const JsonPointer* parent_ = nullptr;  // the enclosing value's pointer; null at the root
  std::string_view key_;                 // the member's key, unescaped (when !is_index_)
  std::size_t index_ = 0;                // the element's 0-based index (when is_index_)
  std::size_t byte_ = 1;                 // 1-based offset of the value's first byte in the text
  bool is_index_ = false;
};

class JsonCursor {
 public:
  /// What the next value is, from its first byte.
  enum class Kind : std::uint8_t { null, boolean, number, string, array, object };

  /// A UTF-8 byte order mark at the start is passed over, as nlohmann does (RFC 8259 8.1 lets a parser
  /// ignore one, and Windows editors write it); byte offsets still count from the text's first byte.
  JsonCursor(std::string_view text, int max_depth)
      : begin_(text.data()),
        p_(text.data() + (text.starts_with("\xEF\xBB\xBF") ? 3 : 0)),
        end_(text.data() + text.size()),
        max_depth_(max_depth) {}

  /// The next value's kind; whitespace before it is skipped. Malformed when there is none.
  [[gnu::always_inline]] Kind peek() {
    space();
    if (p_ == end_) fail("expected a value, got the end of the text");
    switch (*p_) {
      case '{':
        return Kind::object;
      case '[':
        return Kind::array;
      case '"':
        return Kind::string;
      case 't':
      case 'f':
        return Kind::boolean;
      case 'n':
        return Kind::null;
      default:
        if (*p_ == '-' || (*p_ >= '0' && *p_ <= '9')) return Kind::number;
        fail("expected a value");
    }
  }
  /// 1-based byte offset of the next byte (after the whitespace peek() skipped).
  std::size_t offset() const { return static_cast<std::size_t>(p_ - begin_) + 1; }
  /// offset() after the whitespace that is next.
  [[gnu::always_inline]] std::size_t next_offset() {
    space();
    return offset();
  }

  /// '{': true when a member follows (read it with key()), false for "{}".
  [[gnu::always_inline]] bool object_begin() { return open('{', '}'); }
  /// After a member's value: true when ',' and another member follow, false at '}'.
  [[gnu::always_inline]] bool object_next() {
    return next('}', "expected ',' or '}' after an object member");
  }
  /// A member's key and its ':'.
  [[gnu::always_inline]] std::string_view key() {
    space();
    if (p_ == end_ || *p_ != '"') fail("expected a quoted key");
    const std::string_view k = string_body();
    space();
    if (p_ == end_ || *p_ != ':') fail("expected ':' after a key");
    ++p_;
    return k;
  }
  [[gnu::always_inline]] bool array_begin() { return open('[', ']'); }
  [[gnu::always_inline]] bool array_next() { return next(']', "expected ',' or ']' after an array element"); }

  /// A string's content with escapes decoded; valid until the next call that reads a string.
  [[gnu::always_inline]] std::string_view string() {
    if (peek() != Kind::string) fail("expected a string");
    return string_body();
  }
  /// True when the next byte after whitespace is `c`.
  [[gnu::always_inline]] bool at(char c) {
    space();
    return p_ < end_ && *p_ == c;
  }
  /// "[x, y]" of two numbers, the shape of nearly every 2D point, read in one go; false with nothing
  /// consumed for anything else (the caller's general path then reads it, and words its errors).
  [[gnu::always_inline]] bool pair(double& x, double& y) {
    const Mark start = mark();
    if (!at('[') || depth_ + 1 > max_depth_) return false;
    ++p_;
    if (at_number()) {
      x = number_here();
      if (at(',') && (++p_, at_number())) {
        y = number_here();
        if (at(']')) return ++p_, true;
      }
    }
    seek(start);
    return false;
  }
  /// A plain integer in 0..2^32 - 2 ("12"; not "-1", "01", "1.0" or "1e3"): a mesh's index, read in one
  /// go. False with nothing consumed for anything else, which number() then reads.
  [[gnu::always_inline]] bool index(std::uint32_t& out) {
    space();
    const char* const first = p_;
    const char* p = first;
    std::uint64_t v = 0;
    while (p < end_ && is_digit(*p) && p - first < 10) v = v * 10 + static_cast<unsigned>(*p++ - '0');
    if (p == first || (*first == '0' && p - first > 1) || v >= UINT32_MAX) return false;
    if (p < end_ && (is_digit(*p) || *p == '.' || *p == 'e' || *p == 'E')) return false;
    number_start_ = first, integral_ = true, p_ = p;
    out = static_cast<std::uint32_t>(v);
    return true;
  }
  /// True when a number starts here (after whitespace).
  [[gnu::always_inline]] bool at_number() {
    space();
    return p_ < end_ && (*p_ == '-' || is_digit(*p_));
  }
  /// string() where at('"') was just true.
  [[gnu::always_inline]] std::string_view string_here() { return string_body(); }
  /// A number as the nearest double; integer syntax gives +0 for "-0", as an integer parse would. Out of
  /// double's range is malformed, as nlohmann's overflow is; below it is 0, as strtod gives.
  [[gnu::always_inline]] double number() {
    if (!at_number()) fail("expected a number");
    return number_here();
  }
  /// number() where at_number() was just true.
  [[gnu::always_inline]] double number_here() {
    // A local cursor: through the member, every byte read (a char may alias anything) would reload it.
    const char* p = p_;
    const char* const end = end_;
    const char* start = p;
    const bool negative = *p == '-';
    p += negative;
    // The digits go into `mantissa` while the grammar is checked (19 of them fit in 64 bits).
    std::uint64_t mantissa = 0;
    const char* digits = p;
    if (p < end && *p == '0') {
      ++p;
    } else {
      if (p == end || !is_digit(*p)) fail_at(p, "expected a digit");
      for (; p < end && is_digit(*p); ++p) mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
    }
    std::ptrdiff_t fraction = 0;
    if (p < end && *p == '.') {
      const char* first = ++p;
      for (; p < end && is_digit(*p); ++p) mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
      if ((fraction = p - first) == 0) fail_at(p, "expected a digit after '.'");
    }
    const std::ptrdiff_t digit_count = p - digits - (fraction ? 1 : 0);
    const bool exponent = p < end && (*p == 'e' || *p == 'E');
    if (exponent) {
      ++p;
      if (p < end && (*p == '+' || *p == '-')) ++p;
      if (p == end || !is_digit(*p)) fail_at(p, "expected a digit in the exponent");
      while (p < end && is_digit(*p)) ++p;
    }
    p_ = p;
    number_start_ = start;
    const bool integral = integral_ = !fraction && !exponent;
    double v = 0;
    if (!exponent && digit_count <= 19 && mantissa <= (std::uint64_t{1} << 53) && fraction <= 22) {
      // Clinger's fast path: the mantissa and the power of ten are exact doubles, so the one IEEE
      // division is correctly rounded; std::from_chars (also correctly rounded) takes everything else.
      // Nothing here waits for the division: its sign is the text's, and zero is decided by the digits.
      if (fraction == 0) {  // integer syntax: read as an integer would be, so "-0" is +0
        const double i = static_cast<double>(mantissa);
        return negative && mantissa != 0 ? -i : i;
      }
      v = static_cast<double>(mantissa) / kExactPow10[fraction];
      return negative ? -v : v;
    } else if (const auto [last, error] = std::from_chars(digits, p, v); error != std::errc() || last != p) {
      if (error != std::errc::result_out_of_range || overflows(start)) fail_at(start, "number out of range");
      v = 0;
    }
    if (integral && v == 0) return 0.0;
    return negative ? -v : v;
  }
  /// The text of the number just read (before anything else is read), for messages.
  std::string_view number_text() const {
    return {number_start_, static_cast<std::size_t>(p_ - number_start_)};
  }
  /// 1-based byte offset of the number just read.
  std::size_t number_offset() const { return static_cast<std::size_t>(number_start_ - begin_) + 1; }
  /// Whether the last number read was written as an integer (no fraction, no exponent).
  bool integral() const { return integral_; }
  bool boolean() {
    if (peek() == Kind::boolean) {
      if (literal("true")) return true;
      if (literal("false")) return false;
    }
    fail("expected true or false");
  }
  /// A place in the text to read again from, for a second look on an error path.
  struct Mark {
    const char* p;
    int depth;
  };
  Mark mark() const { return {p_, depth_}; }
  void seek(Mark m) { p_ = m.p, depth_ = m.depth; }
  JsonCursor from(Mark m) const {
    JsonCursor c(std::string_view(begin_, static_cast<std::size_t>(end_ - begin_)), max_depth_);
    c.p_ = m.p, c.depth_ = m.depth;
    return c;
  }
  /// True when `s` is a view of the text (not of the buffer of a string whose escapes were decoded).
  bool in_text(std::string_view s) const { return s.data() >= begin_ && s.data() <= end_; }
  /// The element count of the array that starts here when it holds only numbers; else 0. For reserving.
  std::size_t flat_array_size();
  /// How many bytes of `text` equal `c`, 16 at a time.
  static std::size_t count(std::string_view text, char c);
  /// Any value, checked and passed over; its text.
  std::string_view skip();
  /// Only whitespace may remain.
  void finish() {
    space();
    if (p_ != end_) fail("expected the end of the document after the top-level value");
  }

  [[noreturn, gnu::cold]] void fail(std::string_view what) const { fail_at(p_, what); }
  [[noreturn, gnu::cold, gnu::noinline]] void fail_at(const char* at, std::string_view what) const;

 private:
  // Machine-written JSON has little whitespace: one compare decides most calls.
  [[gnu::always_inline]] void space() {
    if (p_ == end_ || static_cast<unsigned char>(*p_) <= 0x20) skip_space();
  }
  void skip_space() {
    const char* p = p_;
    while (p < end_ && (*p == ' ' || *p == '\n' || *p == '\r' || *p == '\t')) ++p;
    p_ = p;
  }
  [[gnu::always_inline]] bool open(char c, char close) {
    space();
    if (p_ == end_ || *p_ != c) fail(c == '{' ? "expected '{'" : "expected '['");
    if (++depth_ > max_depth_) too_deep();  // no tree is built, but a deep document is refused all the same
    ++p_;
    space();
    if (p_ < end_ && *p_ == close) return ++p_, --depth_, false;
    return true;
  }
  [[gnu::always_inline]] bool next(char close, const char* what) {
    if (p_ < end_ && *p_ == ',') return ++p_, true;  // the usual case, without whitespace
    space();
    if (p_ < end_ && *p_ == ',') return ++p_, true;
    if (p_ < end_ && *p_ == close) return ++p_, --depth_, false;
    fail(what);
  }
  bool literal(std::string_view word) {
    if (static_cast<std::size_t>(end_ - p_) < word.size() || std::string_view(p_, word.size()) != word)
      return false;
    p_ += word.size();
    return true;
  }
  static bool is_digit(char c) { return c >= '0' && c <= '9'; }
  static constexpr double kExactPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                           1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                           1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};  // all exact doubles
  // At '"': the usual string, without escapes, is a view of the text; escapes are decoded out of line.
  // Bytes above 0x7F (UTF-8 beyond ASCII) are valid JSON only inside strings: each string that has one is
  // checked here, so a text the cursor reads to its end is well-formed UTF-8 (see parse_scene).
  [[gnu::always_inline]] std::string_view string_body() {
    const char* start = p_ + 1;
    const char* p = start;
    unsigned char high = 0;
    for (unsigned char c; p < end_ && kPlainByte[c = static_cast<unsigned char>(*p)]; ++p) high |= c;
    p_ = p;
    if (p < end_ && *p == '"') {
      if (high & 0x80) require_utf8(start, p);
      return ++p_, std::string_view(start, static_cast<std::size_t>(p - start));
    }
    return escaped_string(start);
  }
  // Throws SceneError(encoding) at the text's first ill-formed byte when [from, to) is not UTF-8.
  void require_utf8(const char* from, const char* to) const;
  std::string_view escaped_string(const char* start);
  [[noreturn, gnu::cold, gnu::noinline]] void too_deep() const;
  // Bytes that stand for themselves in a string: all but '"', '\\' and control characters (bytes above 0x7F
  // are checked as UTF-8 per string, in string_body).
  static constexpr auto kPlainByte = [] {
    std::array<bool, 256> t{};
    for (int c = 0x20; c < 256; ++c) t[c] = c != '"' && c != '\\';
    return t;
  }();
  bool overflows(const char* number) const;  // out of double's range: too large (true) or too small

  const char* begin_;                   // the text's first byte: offsets count from here, 1-based
  const char* p_;                       // the next byte to read
  const char* end_;                     // one past the text's last byte
  int max_depth_;                       // arrays and objects open at once, at most
  int depth_ = 0;                       // arrays and objects open now
  std::string scratch_;                 // the last string that had escapes, decoded
  const char* number_start_ = nullptr;  // the last number read, which ends at p_ until the next read
  bool integral_ = false;               // the last number read had no fraction and no exponent
};

}  // namespace raster
