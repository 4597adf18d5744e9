#include "blend2d_peer.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#if defined(RASTERD_BLEND2D)
#include <blend2d/blend2d.h>
#endif

namespace bench {

#if defined(RASTERD_BLEND2D)

bool blend2d_built() {
  return true;
}

raster::Image blend2d_render(const std::vector<PeerPolygon>& polygons, raster::Rgba8 background, int size,
                             int runs, double* ms) {
  std::vector<double> times;
  raster::Image out{size, size, raster::PixelFormat::rgb8, {}};
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    BLImage image(size, size, BL_FORMAT_XRGB32);
    BLContext ctx(image);  // synchronous: no worker threads
    ctx.fill_all(BLRgba32(background.r, background.g, background.b));
    BLPath path;
    for (const PeerPolygon& p : polygons) {
      path.clear();
      path.move_to(p.points[0][0], p.points[0][1]);
      for (std::size_t k = 1; k < p.points.size(); ++k) path.line_to(p.points[k][0], p.points[k][1]);
      path.close();
      ctx.fill_path(path, BLRgba32(p.color.r, p.color.g, p.color.b, p.color.a));
    }
    ctx.end();
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (r + 1 == runs) {  // XRGB32: a native-endian word a pixel
      BLImageData data;
      image.get_data(&data);
      out.pixels.resize(static_cast<std::size_t>(size) * size * 3);
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
          std::uint32_t v;
          std::memcpy(&v, static_cast<const std::uint8_t*>(data.pixel_data) + y * data.stride + x * 4, 4);
          for (int k = 0; k < 3; ++k)
            out.pixels[(static_cast<std::size_t>(y) * size + x) * 3 + k] =
                static_cast<std::uint8_t>(v >> (16 - 8 * k));
        }
    }
  }
  std::nth_element(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2), times.end());
  *ms = times[times.size() / 2];
  return out;
}

#else

bool blend2d_built() {
  return false;
}

raster::Image blend2d_render(const std::vector<PeerPolygon>&, raster::Rgba8, int, int, double*) {
  std::abort();  // callers ask blend2d_built() first
}

#endif

}  // namespace bench
