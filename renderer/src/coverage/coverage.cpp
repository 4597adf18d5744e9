#include "coverage/coverage.h"

#include <bit>
#include <stdexcept>
#include <string>

namespace raster::detail {

const std::array<double, 2>* centroid_offsets(int samples) {
  // The sums and divisions shading did per pixel, in the same order, so the offsets are the same doubles.
  auto table = [](int n) {
    const std::vector<SamplePoint>& pattern = sample_pattern(n);
    std::vector<std::array<double, 2>> out(std::size_t{1} << n, {0.0, 0.0});
    for (unsigned covered = 1; covered < out.size(); ++covered) {
      double cx = 0, cy = 0;
      for (unsigned k = covered; k; k &= k - 1) {
        const SamplePoint p = pattern[std::countr_zero(k)];
        cx += p.x - 128, cy += p.y - 128;
      }
      const double count = std::popcount(covered) * 256.0;
      out[covered] = {cx / count, cy / count};
    }
    return out;
  };
  static const std::vector<std::array<double, 2>> four = table(4), eight = table(8);
  return samples == 4 ? four.data() : samples == 8 ? eight.data() : nullptr;
}

}  // namespace raster::detail
