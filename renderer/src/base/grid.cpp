#include "base/grid.h"

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>

namespace raster::detail {

const std::vector<SamplePoint>& sample_pattern(int samples) {
  // Direct3D's standard multisample positions, in 1/16 px from the pixel centre, scaled to 1/256 px from
  // the pixel's corner: every position is on the rasterizer's sub-pixel grid.
  auto pattern = [](std::initializer_list<std::pair<int, int>> sixteenths) {
    std::vector<SamplePoint> out;
    for (auto [x, y] : sixteenths) out.push_back({128 + 16 * x, 128 + 16 * y});
    return out;
  };
  static const std::vector<SamplePoint> one{{128, 128}};
  static const std::vector<SamplePoint> four = pattern({{-2, -6}, {6, -2}, {-6, 2}, {2, 6}});
  static const std::vector<SamplePoint> eight =
      pattern({{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}});
  static const std::vector<SamplePoint> sixteen = pattern({{1, 1},
                                                           {-1, -3},
                                                           {-3, 2},
                                                           {4, -1},
                                                           {-5, -2},
                                                           {2, 5},
                                                           {5, 3},
                                                           {3, -5},
                                                           {-2, 6},
                                                           {0, -7},
                                                           {-4, -6},
                                                           {-6, 4},
                                                           {-8, 0},
                                                           {7, -4},
                                                           {6, 7},
                                                           {-7, -8}});
  switch (samples) {
    case 1:
      return one;
    case 4:
      return four;
    case 8:
      return eight;
    case 16:
      return sixteen;
  }
  // The plan takes its counts from kSampleCounts (scene.h): any other is a bug, not a request for 1.
  throw std::logic_error("no sample pattern for " + std::to_string(samples) + " samples a pixel");
}

}  // namespace raster::detail
