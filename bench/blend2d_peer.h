// Blend2D, the 2D peer to beat on error against time (analytic cell coverage, JIT-compiled fill pipelines).
// It is not a Debian package: the bench is built against a Blend2D checkout the developer provides
// (BLEND2D_DIR, docs/accuracy.md says how), and without one says so and leaves its rows out.
#pragma once

#include <array>
#include <vector>

#include "raster/image.h"
#include "raster/scene.h"

namespace bench {

/// A filled polygon (pixels, origin top-left, y down) in one straight-alpha colour.
struct PeerPolygon {
  std::vector<std::array<double, 2>> points;
  raster::Rgba8 color;
};

/// Whether this bench was built against Blend2D.
bool blend2d_built();

/// `polygons` filled in order (non-zero, source-over) over `background` into a size x size XRGB32 image by
/// Blend2D's synchronous context (the calling thread, no workers), `runs` times; the median time of one
/// whole picture (image, context, clear, fills, end) into *ms, and the last picture as RGB. Only when
/// blend2d_built().
raster::Image blend2d_render(const std::vector<PeerPolygon>& polygons, raster::Rgba8 background, int size,
                             int runs, double* ms);

}  // namespace bench
