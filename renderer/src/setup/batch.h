// Mesh triangles sorted eight at a time, before any record is made: a triangle whose snapped bounding box
// holds no sample point of the image (no pixel centre, or multisampled no sample position) draws nothing,
// and most triangles of a dense mesh are such slivers of a pixel. One AVX2 pass finds them for eight
// triangles (their corners gathered, their boxes compared with each sample position); only the others go on
// to the whole set-up (Setup::fast_record and the attributes).
#pragma once

#include <array>
#include <climits>
#include <cstdint>

#include "base/grid.h"
#include "raster/plan.h"

namespace raster::detail {

/// A mesh vertex through the camera, as geometry projects it once for all its triangles.
struct ScreenVertex {
  std::int32_t x, y;  ///< snapped, 1/256 px, origin top-left, y down (inside the guard band: |x| < 2^23);
                      ///< x is kNoScreen (and y 0) for a vertex outside some clip plane
  float depth;        ///< z / w in [0, 1], reversed
  float inv_w;        ///< 1 / w
};
inline constexpr std::int32_t kNoScreen = INT32_MIN;

/// Of the `n` triangles at `triangles` (n <= 8, indices into `screen`), those that need the whole set-up:
/// bit i is set when triangle i has a vertex without a screen position (it may be clipped) or when the box of
/// its vertices holds a sample point of the width x height image: one of the `count` positions of `pattern`
/// (1/256 px in each pixel; the centre alone, (128, 128), without multisampling). A triangle whose bit is
/// clear covers no sample. The same bits on every instruction set.
std::uint32_t sample_candidates(const std::array<std::uint32_t, 3>* triangles, int n,
                                const ScreenVertex* screen, const SamplePoint* pattern, int count, int width,
                                int height, Simd simd);

}  // namespace raster::detail
