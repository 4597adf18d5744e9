// The words of an OBJ line and the numbers in them, for the OBJ reader's passes (obj.cpp): a statement's
// keyword, its words one by one, coordinates as std::from_chars reads them (a fast path for the plain
// decimals exporters print, exact: the same double from_chars gives), and a reference's index resolved as
// OBJ resolves it. Nothing here allocates.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>

#include "raster/scene.h"

namespace raster::obj {

/// What a line states, by its first word. Lines of any other keyword (o, g, s, free-form geometry, ...) and
/// comments draw nothing.
enum class Statement : std::uint8_t { none, v, vt, vn, f, l, p, usemtl, mtllib };

/// One line of the text, without its '\n'; `at` walks its words.
struct LineWords {
  const char* at;
  const char* end;

  static bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
  /// The next word, or an empty one at the line's end.
  std::string_view next() {
    while (at < end && blank(*at)) ++at;
    const char* start = at;
    while (at < end && !blank(*at)) ++at;
    return {start, static_cast<std::size_t>(at - start)};
  }
  /// The words left, counted (the walk is not moved).
  std::size_t count() const {
    LineWords copy = *this;
    std::size_t n = 0;
    while (!copy.next().empty()) ++n;
    return n;
  }
  /// The rest of the line after the blanks that follow the keyword.
  std::string_view rest() const {
    const char* p = at;
    while (p < end && blank(*p)) ++p;
    return {p, static_cast<std::size_t>(end - p)};
  }
};

/// Whether `line` (without its '\n') holds a carriage return with something other than blanks after it: a
/// line end of classic Mac OS, which tinyobjloader took for one, and which rasterd refuses rather than read
/// the rest as more of the same statement. A CR before the '\n' (CR LF) is a blank.
inline bool inner_carriage_return(std::string_view line) {
  for (std::size_t cr = line.find('\r'); cr != std::string_view::npos; cr = line.find('\r', cr + 1))
    for (std::size_t k = cr + 1; k < line.size() && line[k] != '\r'; ++k)
      if (!LineWords::blank(line[k])) return true;
  return false;
}

/// The digits of a plain decimal, as number() takes them: [-]digits[.digits], with the integer they make and
/// how many follow the point. `at` is left at the first character that is not part of it.
struct Decimal {
  std::uint64_t digits = 0;
  int count = 0;         ///< digits taken (at most 19 fit; more go to std::from_chars)
  int after_point = -1;  ///< digits after the '.'; -1: no point
  bool negative = false;
};
inline const char* scan_decimal(const char* at, const char* end, Decimal& d) {
  d.negative = at < end && *at == '-';
  at += d.negative;
  for (; at < end; ++at) {
    const unsigned k = static_cast<unsigned>(*at - '0');
    if (k < 10) {
      d.digits = d.digits * 10 + k, ++d.count;
      d.after_point += d.after_point >= 0;
    } else if (*at == '.' && d.after_point < 0) {
      d.after_point = 0;
    } else {
      break;
    }
  }
  return at;
}

/// The decimal's value when Clinger's fast path gives it exactly (at most 18 digits making less than 2^53,
/// divided by a power of ten at most 10^18: IEEE division rounds once, to the double from_chars gives).
inline bool fast_value(const Decimal& d, double& out) {
  static constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8, 1e9,
                                       1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18};
  if (d.count == 0 || d.count > 18 || d.digits >= (std::uint64_t{1} << 53)) return false;
  const double v = static_cast<double>(d.digits) / kPowers[d.after_point < 0 ? 0 : d.after_point];
  out = d.negative ? -v : v;
  return true;
}

/// The statement a line's first word names; `words` is left after it.
inline Statement statement(LineWords& words) {
  const std::string_view key = words.next();
  if (key.empty() || key[0] == '#') return Statement::none;
  switch (key.size()) {
    case 1:
      return key[0] == 'v'   ? Statement::v
             : key[0] == 'f' ? Statement::f
             : key[0] == 'l' ? Statement::l
             : key[0] == 'p' ? Statement::p
                             : Statement::none;
    case 2:
      return key == "vt" ? Statement::vt : key == "vn" ? Statement::vn : Statement::none;
    case 6:
      return key == "usemtl" ? Statement::usemtl : key == "mtllib" ? Statement::mtllib : Statement::none;
    default:
      return Statement::none;
  }
}

/// A number as OBJ writers print it and strtod reads it, the whole word: std::from_chars's grammar with a
/// leading '+' allowed ("+1", assimp's number_formats.obj). False when the word is not one, or is not finite.
/// Plain decimals of at most 18 digits take a path of their own: the digits as an integer, divided (or
/// multiplied) by an exact power of ten at most 10^22, which IEEE arithmetic rounds once, to the same double
/// from_chars gives (Clinger's fast path); anything else goes to from_chars.
inline bool number(std::string_view w, double& out) {
  if (w.size() > 1 && w[0] == '+' && w[1] != '-' && w[1] != '+') w.remove_prefix(1);
  const char* const end = w.data() + w.size();
  Decimal d;
  if (scan_decimal(w.data(), end, d) == end && fast_value(d, out)) return true;
  double v = 0;
  const auto [q, ec] = std::from_chars(w.data(), end, v);
  if (ec != std::errc() || q != end || !std::isfinite(v)) return false;
  out = v;
  return true;
}

/// The next word of `words` as number() reads it: false when it is not a number; `present` false (and
/// false returned) when the line has no more words. The plain decimal of every exporter is read in one
/// pass over its characters.
inline bool next_number(LineWords& words, double& out, bool& present) {
  while (words.at < words.end && LineWords::blank(*words.at)) ++words.at;
  present = words.at < words.end;
  if (!present) return false;
  const char* start = words.at;
  Decimal d;
  const char* stop = scan_decimal(start, words.end, d);
  if ((stop == words.end || LineWords::blank(*stop)) && fast_value(d, out)) {
    words.at = stop;
    return true;
  }
  words.at = start;
  return number(words.next(), out);
}

/// As tinyobjloader reads a normal's component: the number at the start of the word, 0 when there is none or
/// it is not finite (a normal of "nan" is no direction; the lighting then takes the face's side).
inline double lenient_number(std::string_view w) {
  if (w.size() > 1 && w[0] == '+' && w[1] != '-' && w[1] != '+') w.remove_prefix(1);
  double d = 0;
  const auto [q, ec] = std::from_chars(w.data(), w.data() + w.size(), d);
  return ec == std::errc() && std::isfinite(d) ? d : 0;
}

/// One index of a reference ("v", "v/vt", "v//vn", "v/vt/vn"), resolved as OBJ resolves it: 1-based, a
/// negative one counted back from the last defined so far. The 0-based index, or -1 when `text` is not an
/// integer, is 0, or names nothing defined so far (`defined` of them): the caller words the error.
inline std::int64_t resolve(std::string_view text, std::int64_t defined) {
  const char* p = text.data();
  const char* const end = p + text.size();
  const bool negative = p < end && *p == '-';
  p += negative;
  if (p == end || end - p > 18) {
    std::int64_t value = 0;  // long or empty: as std::from_chars reads it (overflow is out of range)
    const auto [q, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || q != end || value == 0) return -1;
    const std::int64_t resolved = value < 0 ? defined + value : value - 1;
    return resolved >= 0 && resolved < defined ? resolved : -1;
  }
  std::int64_t value = 0;
  for (; p < end; ++p) {
    const unsigned d = static_cast<unsigned>(*p - '0');
    if (d >= 10) return -1;
    value = value * 10 + d;
  }
  if (value == 0) return -1;
  const std::int64_t resolved = negative ? defined - value : value - 1;
  return resolved >= 0 && resolved < defined ? resolved : -1;
}

/// A reference's three parts ("v", "v/vt", "v//vn", "v/vt/vn"): `texture` and `normal` empty when absent.
struct Reference {
  std::string_view vertex, texture, normal;
  bool has_normal = false;  ///< "v//vn" or "v/vt/vn" (a normal part follows a second '/')
};
inline Reference split_reference(std::string_view ref) {
  Reference r;
  const std::size_t s1 = ref.find('/');
  r.vertex = ref.substr(0, s1);
  if (s1 == std::string_view::npos) return r;
  const std::size_t s2 = ref.find('/', s1 + 1);
  r.texture = ref.substr(s1 + 1, s2 == std::string_view::npos ? std::string_view::npos : s2 - s1 - 1);
  if (s2 != std::string_view::npos) r.normal = ref.substr(s2 + 1), r.has_normal = true;
  return r;
}

/// parse_obj with the text cut into pieces of at least `piece_bytes` (to a line end) where parse_obj takes
/// 1 MiB: a test's way to put a piece boundary between any two lines. The same mesh and the same errors
/// for any piece size and thread count (Limits::threads).
Mesh read_obj_text(std::string_view obj_text, std::string_view mtl_text, const Limits& limits,
                   const Uploads& files, std::size_t piece_bytes);

/// Checks `text` line after line as OBJ reads it, and throws the first error a reader of the lines in order
/// meets, in the words rasterd has always used (obj_check.cpp): a vertex, texture coordinate or normal
/// without its numbers, a number that is not one or beyond its range, a face, line or point without enough
/// references, a reference that is not an integer or names nothing defined so far, and the faces or points
/// past the limits, each naming its line. Returns normally when there is none. The fast passes of the reader
/// (obj.cpp) only notice that something is wrong; this says what.
void check_obj_text(std::string_view text, const Limits& limits);

}  // namespace raster::obj
