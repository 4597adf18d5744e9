#include "base/wide.h"

#include <cmath>

namespace raster::detail {

Wide::Wide(std::int64_t v) {
  limb_[0] = static_cast<std::uint64_t>(v);
  const std::uint64_t fill = v < 0 ? ~std::uint64_t{0} : 0;
  for (int i = 1; i < kLimbs; ++i) limb_[i] = fill;
}

Wide Wide::from_double(double integral) {
  int exponent = 0;
  const double fraction = std::frexp(std::fabs(integral), &exponent);  // |v| = fraction * 2^exponent
  // 53 significant bits as an integer, then shifted into place (exponent - 53 >= 0 for |v| >= 2^53;
  // smaller integral values are exact in int64 directly).
  if (exponent <= 62) return Wide(static_cast<std::int64_t>(integral));
  auto mantissa = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
  const int shift = exponent - 53;
  Wide out;
  const int whole = shift / 64, bits = shift % 64;
  out.limb_[whole] = mantissa << bits;
  if (bits != 0 && whole + 1 < kLimbs) out.limb_[whole + 1] = mantissa >> (64 - bits);
  return integral < 0 ? -out : out;
}

Wide operator+(const Wide& a, const Wide& b) {
  Wide r;
  unsigned carry = 0;
  for (int i = 0; i < Wide::kLimbs; ++i) {
    const unsigned __int128 s = static_cast<unsigned __int128>(a.limb_[i]) + b.limb_[i] + carry;
    r.limb_[i] = static_cast<std::uint64_t>(s);
    carry = static_cast<unsigned>(s >> 64);
  }
  return r;
}

Wide Wide::operator-() const {
  Wide r;
  for (int i = 0; i < kLimbs; ++i) r.limb_[i] = ~limb_[i];
  return r + Wide(1);
}

Wide operator-(const Wide& a, const Wide& b) {
  return a + (-b);
}

// Schoolbook product modulo 2^384; two's complement makes it right for signed operands too.
Wide operator*(const Wide& a, const Wide& b) {
  Wide r;
  for (int i = 0; i < Wide::kLimbs; ++i) {
    if (a.limb_[i] == 0) continue;
    std::uint64_t carry = 0;
    for (int j = 0; i + j < Wide::kLimbs; ++j) {
      const unsigned __int128 p =
          static_cast<unsigned __int128>(a.limb_[i]) * b.limb_[j] + r.limb_[i + j] + carry;
      r.limb_[i + j] = static_cast<std::uint64_t>(p);
      carry = static_cast<std::uint64_t>(p >> 64);
    }
  }
  return r;
}

std::strong_ordering operator<=>(const Wide& a, const Wide& b) {
  if (a.negative() != b.negative())
    return a.negative() ? std::strong_ordering::less : std::strong_ordering::greater;
  for (int i = Wide::kLimbs - 1; i >= 0; --i)
    if (a.limb_[i] != b.limb_[i])
      return a.limb_[i] < b.limb_[i] ? std::strong_ordering::less : std::strong_ordering::greater;
  return std::strong_ordering::equal;
}

double Wide::to_double() const {
  if (negative()) return -(-*this).to_double();
  double d = 0;
  for (int i = kLimbs - 1; i >= 0; --i) d = d * 0x1p64 + static_cast<double>(limb_[i]);
  return d;
}

namespace {

// Shared by both integer types: range checks by multiplication, then a floating estimate corrected by
// exact comparisons. Within [lo, hi] the quotient has at most ~50 bits, so the estimate is off by <= 1.
template <typename T>
std::int64_t floor_div_clamped_impl(const T& n, const T& d, std::int64_t lo, std::int64_t hi, double nd,
                                    double dd) {
  if (n < d * T(lo)) return lo;
  if (!(n < d * (T(hi) + T(1)))) return hi;
  double estimate = std::floor(nd / dd);
  std::int64_t q = estimate < static_cast<double>(lo)   ? lo
                   : estimate > static_cast<double>(hi) ? hi
                                                        : static_cast<std::int64_t>(estimate);
  while (n < d * T(q)) --q;
  while (!(n < d * (T(q) + T(1)))) ++q;
  return q;
}

}  // namespace

std::int64_t floor_div_clamped(const Wide& n, const Wide& d, std::int64_t lo, std::int64_t hi) {
  return floor_div_clamped_impl(n, d, lo, hi, n.to_double(), d.to_double());
}

std::int64_t floor_div_clamped(__int128 n, __int128 d, std::int64_t lo, std::int64_t hi) {
  return floor_div_clamped_impl(n, d, lo, hi, static_cast<double>(n), static_cast<double>(d));
}

}  // namespace raster::detail
