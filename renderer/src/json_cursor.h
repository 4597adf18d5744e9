// A validating pull tokenizer over JSON text (RFC 8259): the scene reader asks for the value it expects
// next and the cursor either gives it or throws SceneError(syntax) with the 1-based byte offset of the
// first byte that cannot belong to a well-formed document.
//
// Why our own and not RapidJSON's SAX Reader: pulled values let a descriptor's reader read its field
// where it stands (a point straight into the scene's array) instead of a state machine driven by events,
// and it measured faster on the bench scenes (docs/performance.md, "JSON tokenizer"). The text must already
// be well-formed UTF-8 (parse_scene checks it first); escapes are checked here, lone surrogates included.
#pragma once

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
  std::string str() const {
    if (!parent_) return "";
    std::string out = parent_->str() + "/";
    if (is_index_) return out + std::to_string(index_);
    for (char c : key_) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);  // RFC 6901
    return out;
  }

 private:
  const JsonPointer* parent_ = nullptr;
  std::string_view key_;
  std::size_t index_ = 0, byte_ = 1;
  bool is_index_ = false;
};

class JsonCursor {
 public:
  /// What the next value is, from its first byte.
  enum class Kind : std::uint8_t { null, boolean, number, string, array, object };

  JsonCursor(std::string_view text, int max_depth)
      : begin_(text.data()), p_(text.data()), end_(text.data() + text.size()), max_depth_(max_depth) {}

  /// The next value's kind; whitespace before it is skipped. Malformed when there is none.
  Kind peek() {
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
  std::size_t next_offset() {
    space();
    return offset();
  }

  /// '{': true when a member follows (read it with key()), false for "{}".
  bool object_begin() { return open('{', '}'); }
  /// After a member's value: true when ',' and another member follow, false at '}'.
  bool object_next() { return next('}', "expected ',' or '}' after an object member"); }
  /// A member's key and its ':'.
  std::string_view key() {
    space();
    if (p_ == end_ || *p_ != '"') fail("expected a quoted key");
    const std::string_view k = string_body();
    space();
    if (p_ == end_ || *p_ != ':') fail("expected ':' after a key");
    ++p_;
    return k;
  }
  bool array_begin() { return open('[', ']'); }
  bool array_next() { return next(']', "expected ',' or ']' after an array element"); }

  /// A string's content with escapes decoded; valid until the next call that reads a string.
  std::string_view string() {
    if (peek() != Kind::string) fail("expected a string");
    return string_body();
  }
  /// True when the next byte after whitespace is `c`.
  bool at(char c) {
    space();
    return p_ < end_ && *p_ == c;
  }
  /// True when a number starts here (after whitespace).
  bool at_number() {
    space();
    return p_ < end_ && (*p_ == '-' || is_digit(*p_));
  }
  /// A number as the nearest double; integer syntax gives +0 for "-0", as an integer parse would. Out of
  /// double's range is malformed, as nlohmann's overflow is; below it is 0, as strtod gives.
  double number() {
    if (!at_number()) fail("expected a number");
    const char* start = p_;
    const bool negative = *p_ == '-';
    p_ += negative;
    // The digits go into `mantissa` while the grammar is checked (19 of them fit in 64 bits).
    std::uint64_t mantissa = 0;
    const char* digits = p_;
    if (p_ < end_ && *p_ == '0') {
      ++p_;
    } else {
      if (p_ == end_ || !is_digit(*p_)) fail("expected a digit");
      for (; p_ < end_ && is_digit(*p_); ++p_) mantissa = mantissa * 10 + static_cast<unsigned>(*p_ - '0');
    }
    std::ptrdiff_t fraction = 0;
    if (p_ < end_ && *p_ == '.') {
      const char* first = ++p_;
      for (; p_ < end_ && is_digit(*p_); ++p_) mantissa = mantissa * 10 + static_cast<unsigned>(*p_ - '0');
      if ((fraction = p_ - first) == 0) fail("expected a digit after '.'");
    }
    const std::ptrdiff_t digit_count = p_ - digits - (fraction ? 1 : 0);
    const bool exponent = p_ < end_ && (*p_ == 'e' || *p_ == 'E');
    if (exponent) {
      ++p_;
      if (p_ < end_ && (*p_ == '+' || *p_ == '-')) ++p_;
      if (p_ == end_ || !is_digit(*p_)) fail("expected a digit in the exponent");
      while (p_ < end_ && is_digit(*p_)) ++p_;
    }
    number_text_ = {start, static_cast<std::size_t>(p_ - start)};
    const bool integral = !fraction && !exponent;
    double v = 0;
    if (!exponent && digit_count <= 19 && mantissa <= (std::uint64_t{1} << 53) && fraction <= 22) {
      // Clinger's fast path: the mantissa and the power of ten are exact doubles, so the one IEEE
      // division is correctly rounded; std::from_chars (also correctly rounded) takes everything else.
      v = static_cast<double>(mantissa) / kExactPow10[fraction];
    } else if (const auto [end, error] = std::from_chars(digits, p_, v); error != std::errc() || end != p_) {
      if (error != std::errc::result_out_of_range || overflows(start)) fail_at(start, "number out of range");
      v = 0;
    }
    if (integral && v == 0) return 0.0;
    return negative ? -v : v;
  }
  /// The text of the last number read, for messages.
  std::string_view number_text() const { return number_text_; }
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
  JsonCursor at(Mark m) const {
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

  [[noreturn]] void fail(std::string_view what) const { fail_at(p_, what); }
  [[noreturn]] void fail_at(const char* at, std::string_view what) const;

 private:
  void space() {
    while (p_ < end_ && static_cast<unsigned char>(*p_) <= ' ' &&
           (*p_ == ' ' || *p_ == '\n' || *p_ == '\r' || *p_ == '\t'))
      ++p_;
  }
  bool open(char c, char close) {
    space();
    if (p_ == end_ || *p_ != c) fail(c == '{' ? "expected '{'" : "expected '['");
    if (++depth_ > max_depth_)  // the tree is never built, but a deep document is refused all the same
      throw SceneError(ErrorKind::syntax, "JSON nested deeper than " + std::to_string(max_depth_) + " levels",
                       ErrorLocation{"", offset(), 0});
    ++p_;
    space();
    if (p_ < end_ && *p_ == close) return ++p_, --depth_, false;
    return true;
  }
  bool next(char close, const char* what) {
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
  std::string_view string_body();                                                      // at '"'
  bool overflows(const char* number) const;  // out of double's range: too large (true) or too small

  const char* begin_;
  const char* p_;
  const char* end_;
  int max_depth_;
  int depth_ = 0;
  std::string scratch_;  // a string with escapes, decoded
  std::string_view number_text_;
};

}  // namespace raster
