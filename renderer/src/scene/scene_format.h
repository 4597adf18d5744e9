// Scene format v1, the parts that more than the reader needs: the ranges of its numbers, which validate()
// applies to scenes built in code with the same words, and the shape of a field descriptor. The tables
// of fields themselves are in scene_reader.cpp and scene_objects.cpp, next to the functions that read them.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include "raster/scene.h"

namespace raster::format {

/// Where a number may lie; `rule` is the sentence a rejection starts with.
struct Range {
  double lo, hi;          ///< the bounds, in the field's own unit (pixels, degrees, world units, 0..1)
  bool lo_open, hi_open;  ///< the bound itself is excluded
  const char* rule;       ///< the sentence an error starts with, naming the field and the range
  bool contains(double v) const {  // false for NaN
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
};

inline constexpr double kInf = std::numeric_limits<double>::infinity();
/// The up axes by name (checks::up_axis), in the order of kUpAxes.
inline constexpr std::array<std::string_view, 9> kUpAxisNames = {"+x", "-x", "+y", "-y", "+z",
                                                                 "-z", "x",  "y",  "z"};
inline constexpr Vec3 kUpAxes[] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1},
                                   {0, 0, -1}, {1, 0, 0},  {0, 1, 0}, {0, 0, 1}};
/// How a bad "antialias" is refused (the value as sent follows).
inline constexpr std::string_view kAntialiasRule =
    "\"antialias\" is \"area\", \"auto\" or the samples per pixel: 1, 4, 8 or 16; got ";
inline constexpr Range kLineWidth{0, 4096, true, false,
                                  "line \"width\" is in pixels, more than 0 and at most 4096"};
inline constexpr Range kEdgeWidth{0, 64, true, false, "edge width is in (0, 64] pixels"};
inline constexpr Range kPointSize{0, 64, true, false, "\"point_size\" is in (0, 64] pixels"};
inline constexpr Range kCreaseAngle{0, 180, false, false, "the crease angle is in 0..180 degrees"};
inline constexpr Range kFov{0, 180, true, true,
                            "\"fov\" is the vertical field of view in degrees, strictly between 0 and 180"};
inline constexpr Range kNear{0, kInf, true, true,
                             "\"near\" is a distance in front of the eye and must be > 0"};
inline constexpr Range kFar{0, kInf, true, true, "\"far\" must be > 0"};
inline constexpr Range kViewHeight{0, kInf, true, true, "\"height\" (orthographic view height) must be > 0"};
inline constexpr Range kAmbient{0, 1, false, false, "\"ambient\" is in 0..1"};
inline constexpr Range kIntensity{0, kMaxLightIntensity, false, false, "\"intensity\" is in 0..1000"};
static_assert(kMaxLightIntensity == 1000, "kIntensity's rule names the limit");
inline constexpr Range kShaderInput{-1e9, 1e9, false, false, "a shader's input is a number within +-1e9"};
inline constexpr Range kTexCoord{-1e30, 1e30, false, false,
                                 "a texture coordinate must be a number within +-1e30"};

/// A number outside its range, in the words of every field that has one.
inline std::string out_of_range(const Range& range, std::string_view text) {
  return std::string(range.rule) + "; got " + std::string(text);
}

/// A coordinate past +-kMaxCoordinate.
inline std::string outside_coordinates(std::string_view text) {
  return "coordinate " + std::string(text) + " is outside +-3.4e38 (+-2^128)";
}

/// A colour string that is none of the hex forms.
inline std::string bad_hex_color(std::string_view text) {
  return "expected a colour \"#rgb\", \"#rgba\", \"#rrggbb\" or \"#rrggbbaa\", got \"" + std::string(text) +
         "\"";
}

/// The names a word field takes, in its errors' words: `expected "a", "b" or "c"`.
inline std::string expected_one_of(std::span<const std::string_view> names) {
  std::string expected = "expected";
  for (std::size_t i = 0; i < names.size(); ++i)
    expected += (i == 0 ? " \"" : i + 1 == names.size() ? " or \"" : ", \"") + std::string(names[i]) + "\"";
  return expected;
}

/// The words of a camera's "projection", "view" and "fit", in the enums' order.
inline constexpr std::array<std::string_view, 2> kProjectionNames{"perspective", "orthographic"};
inline constexpr std::array<std::string_view, 8> kViewNames{"front", "back",   "left", "right",
                                                            "top",   "bottom", "iso",  "three-quarter"};
inline constexpr std::array<std::string_view, 2> kFitNames{"sphere", "vertices"};

/// JSON value kinds as bits, for a descriptor's accepted kinds (JsonCursor::Kind order).
enum KindBits : std::uint8_t {
  kNull = 1,
  kBool = 2,
  kNumber = 4,
  kString = 8,
  kArray = 16,
  kObject = 32,
};

/// One key of one object kind: the kinds of value it takes and the function that reads it (into the state
/// of the object being read). "expected <expected>, got <kind>" is the error for a value of another kind.
template <class Read>
struct Field {
  std::string_view key;  ///< the JSON key, as written
  std::uint8_t kinds;    ///< KindBits the value may be
  const char* expected;  ///< what the value should be, in words: "an array of points"
  Read read;             ///< reads the value, which starts at the cursor, into the object's state
};

/// The bit of each key of `keys` in a table of fields (a key not in the table is a build error).
template <class F, std::size_t N>
requires(N <= 64)  // masks of fields are 64 bits
    constexpr std::uint64_t mask_of(const F (&fields)[N], std::initializer_list<std::string_view> keys) {
  std::uint64_t mask = 0;
  for (std::string_view k : keys) {
    std::size_t i = 0;
    while (fields[i].key != k) ++i;  // runs off the table (not a constant expression) for a wrong key
    mask |= std::uint64_t{1} << i;
  }
  return mask;
}

}  // namespace raster::format
