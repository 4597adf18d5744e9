#include "base/srgb.h"

#include <cmath>
#include <limits>

namespace raster::detail {
namespace {

double srgb_decode(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace

SrgbTables::SrgbTables() {
  for (int i = 0; i < 256; ++i) to_linear[i] = static_cast<float>(srgb_decode(i / 255.0));
  for (int i = 0; i < 255; ++i) threshold[i] = static_cast<float>(srgb_decode((i + 0.5) / 255.0));
  threshold[255] = std::numeric_limits<float>::infinity();
  for (int k = 0, b = 0; k <= kBuckets; ++k) {
    while (b < 255 && threshold[b] < static_cast<float>(k) / kBuckets) ++b;
    below[k] = static_cast<std::uint8_t>(b);
  }
}

const SrgbTables kSrgbTables;

}  // namespace raster::detail
