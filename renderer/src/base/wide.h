// Wide: exact signed integers for the rare geometry beyond the fixed-point fast path (coordinates up to
// 2^128 px). Only what coverage needs: add, subtract, multiply, compare, and division whose quotient is
// clamped to a small range.
#pragma once

#include <array>
#include <compare>
#include <cstdint>

namespace raster::detail {

/// 384-bit two's complement integer. Callers keep magnitudes below 2^380: snapped coordinates are below
/// 2^137, so edge-function values (products of two differences, plus a product) stay below 2^277.
class Wide {
 public:
  static constexpr int kLimbs = 6;

  Wide() = default;
  Wide(std::int64_t v);  // NOLINT(google-explicit-constructor): mixes with int64 literals in formulas

  /// Exact for integer-valued doubles with |v| < 2^380.
  static Wide from_double(double integral);

  friend Wide operator+(const Wide& a, const Wide& b);
  friend Wide operator-(const Wide& a, const Wide& b);
  friend Wide operator*(const Wide& a, const Wide& b);
  Wide operator-() const;
  Wide& operator+=(const Wide& b) { return *this = *this + b; }
  Wide& operator-=(const Wide& b) { return *this = *this - b; }

  friend std::strong_ordering operator<=>(const Wide& a, const Wide& b);
  friend bool operator==(const Wide& a, const Wide& b) = default;

  bool negative() const { return static_cast<std::int64_t>(limb_[kLimbs - 1]) < 0; }
  /// Nearest double (within a few ulps); for colour weights, never for coverage.
  double to_double() const;
  /// The value, when the caller knows it lies within int64.
  std::int64_t low64() const { return static_cast<std::int64_t>(limb_[0]); }

 private:
  std::array<std::uint64_t, kLimbs> limb_{};  // little-endian
};

/// floor(n / d) for d > 0, clamped to [lo, hi], exact.
std::int64_t floor_div_clamped(const Wide& n, const Wide& d, std::int64_t lo, std::int64_t hi);
/// The same for 128-bit integers (the fast line path).
std::int64_t floor_div_clamped(__int128 n, __int128 d, std::int64_t lo, std::int64_t hi);

}  // namespace raster::detail
