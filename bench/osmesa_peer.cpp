// The peer: the same seeded scenes drawn through Mesa's OSMesa (gallium llvmpipe: JIT-compiled SIMD,
// tiles, threads), timed from the first GL call to glFinish. Thread count comes from LP_NUM_THREADS,
// which llvmpipe reads once per process, so `make bench` runs this binary once per thread count.
// Prints: scene raster_ms (median), one line per scene.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "scenes.h"

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 11;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  if (!ctx) {
    std::fprintf(stderr, "osmesa_peer: no OSMesa context\n");
    return 1;
  }
  std::vector<unsigned char> buffer(1024 * 1024 * 4);
  if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 1024, 1024)) return 1;
  for (const char* kind : {"small", "large", "grid"}) {
    const raster::Scene s = bench::make_scene(kind, 1);
    // Vertex arrays of the same triangles: pixel coordinates, per-vertex colours (flat ones repeated).
    std::vector<float> xy;
    std::vector<unsigned char> rgba;
    for (const raster::Primitive& p : s.primitives)
      for (std::uint32_t k = 0; k < 3; ++k) {
        const raster::Point2& q = s.points[p.first_point + k];
        xy.push_back(static_cast<float>(q.x)), xy.push_back(static_cast<float>(q.y));
        const raster::Rgba8 c = s.colors[p.first_color + (p.per_vertex_color ? k : 0)];
        rgba.insert(rgba.end(), {c.r, c.g, c.b, c.a});
      }
    glViewport(0, 0, s.width, s.height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, s.width, s.height, 0, -1, 1);  // pixel coordinates, y down, like rasterd
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, xy.data());
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, rgba.data());
    std::vector<double> ms;
    for (int r = 0; r < runs; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      glClearColor(0, 0, 0, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(xy.size() / 2));
      glFinish();
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    std::printf("%s %.3f\n", kind, ms[ms.size() / 2]);
  }
  OSMesaDestroyContext(ctx);
}
