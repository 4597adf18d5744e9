// Colour bytes: a channel value to its byte, and the sRGB curve both ways as exact tables. Every stage that
// turns a colour into bytes (a line's endpoint colours in geometry, texels filtered into mip levels, pixels
// in shade) rounds through these, so a colour becomes the same byte wherever it is made.
#pragma once

#include <array>
#include <cstdint>

namespace raster::detail {

/// A channel value (0..255 scale) rounded to a byte; out-of-range values clamp and NaN becomes 0, so a
/// float never reaches an integer conversion it cannot survive.
inline std::uint8_t to_byte(double x) {
  if (!(x > 0)) return 0;  // also NaN
  return x >= 254.5 ? 255 : static_cast<std::uint8_t>(x + 0.5);
}

/// The sRGB curve as tables, built once (srgb.cpp).
struct SrgbTables {
  std::array<float, 256> to_linear;  ///< byte -> linear light in 0..1
  // linear -> byte: the byte whose interval [decode(b - 1/2), decode(b + 1/2)) holds the value, i.e. the
  // number of the 255 thresholds between neighbouring bytes that are <= the value (exact rounding in the
  // encoded domain). Found in O(1): the thresholds are at least decode(1.5/255) - decode(0.5/255) = 3.0e-4
  // apart, wider than a bucket of 1/kBuckets = 2.4e-4, so a bucket holds at most one threshold, and the
  // byte is the count below the bucket's start plus one comparison.
  static constexpr int kBuckets = 4096;
  std::array<float, 256> threshold;  ///< 255 used; [255] = +inf so the comparison never runs past the end
  std::array<std::uint8_t, kBuckets + 1> below;  ///< thresholds < bucket k's start k / kBuckets
  SrgbTables();
};
extern const SrgbTables kSrgbTables;

/// sRGB byte -> linear light in 0..1.
inline float srgb_to_linear(std::uint8_t v) {
  return kSrgbTables.to_linear[v];
}

/// Linear light -> sRGB byte, rounded to nearest in the encoded domain; <= 0 and NaN give 0, >= 1 gives 255.
inline std::uint8_t linear_to_srgb(float v) {
  if (!(v > 0)) return 0;  // and NaN
  if (v >= 1) return 255;
  int b = kSrgbTables.below[static_cast<int>(v * SrgbTables::kBuckets)];
  b += v >= kSrgbTables.threshold[b];  // the one threshold this bucket may hold
  return static_cast<std::uint8_t>(b);
}

}  // namespace raster::detail
