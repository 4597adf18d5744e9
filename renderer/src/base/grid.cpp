#include "base/grid.h"

#include <cmath>

namespace raster::detail {

double snap(double px) {
  const double units = px * static_cast<double>(kSubpixelScale);  // exact: a power-of-two scale
  // From 2^52 up every double is already an integer; adding 0.5 there would round to even instead.
  return std::fabs(units) >= 0x1p52 ? units : std::floor(units + 0.5);
}

}  // namespace raster::detail
