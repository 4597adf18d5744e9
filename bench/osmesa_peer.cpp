// The peer: the same seeded scenes drawn through Mesa's OSMesa (gallium llvmpipe: JIT-compiled SIMD,
// tiles, threads), timed from the first GL call to glFinish. Thread count comes from LP_NUM_THREADS,
// which llvmpipe reads once per process, so `make bench` runs this binary once per thread count.
// Prints: scene raster_ms (median), one line per scene. The 3D scenes ("sphere", "bunny") are drawn with
// rasterd's own camera (the plan's world-to-clip matrix, its reversed depth turned into GL's), indexed
// vertex arrays, a depth test and one directional light plus ambient, smooth (Gouraud) shading.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "raster/plan.h"
#include "scenes.h"

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 11;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!ctx) {
    std::fprintf(stderr, "osmesa_peer: no OSMesa context\n");
    return 1;
  }
  std::vector<unsigned char> buffer(1024 * 1024 * 4);
  if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 1024, 1024)) return 1;
  for (const char* kind : {"small", "large", "flat", "grid"}) {
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
    glDisable(GL_LIGHTING);
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
  for (const char* kind : {"sphere", "bunny"}) {
    raster::Scene s;
    try {
      s = bench::mesh_scene(kind);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "osmesa_peer: %s\n", e.what());
      continue;
    }
    const raster::RenderPlan plan = raster::plan(s);
    const raster::Mesh& m = s.meshes[0];
    // Area-weighted vertex normals (rasterd weighs by angle; the lighting work is the same).
    std::vector<float> xyz, normal(m.positions.size() * 3, 0.0f);
    for (const raster::Vec3& p : m.positions)
      xyz.insert(xyz.end(), {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
    std::vector<GLuint> index;
    for (const auto& t : m.triangles) {
      const raster::Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
      const double u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, v[3] = {c.x - a.x, c.y - a.y, c.z - a.z};
      const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      for (int k = 0; k < 3; ++k) {
        index.push_back(t[k]);
        for (int d = 0; d < 3; ++d) normal[t[k] * 3 + d] += static_cast<float>(n[d]);
      }
    }
    // GL matrices are column-major; rasterd's clip z runs 0 (far) .. w (near), GL's -w (near) .. w (far).
    const raster::Mat4& mvp = plan.view.world_to_clip;
    double gl[16];
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) gl[c * 4 + r] = r == 2 ? mvp(3, c) - 2 * mvp(2, c) : mvp(r, c);
    glViewport(0, 0, s.width, s.height);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixd(gl);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    // The scenes it draws are lit by ambient plus one directional light (bench/scenes.cpp): GL's model
    // ambient and LIGHT0.
    float amb = 0, dif = 0;
    raster::Vec3 to_light{0, 0, 1};
    for (const raster::LightPlan& l : plan.view.lights) {
      if (l.kind == raster::LightKind::ambient) amb += static_cast<float>(l.rgb[0]);
      if (l.kind == raster::LightKind::directional) dif = static_cast<float>(l.rgb[0]), to_light = l.to_light;
    }
    const float ambient[4] = {amb, amb, amb, 1}, diffuse[4] = {dif, dif, dif, 1}, none[4] = {0, 0, 0, 1};
    const float dir[4] = {static_cast<float>(to_light.x), static_cast<float>(to_light.y),
                          static_cast<float>(to_light.z), 0};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glLightfv(GL_LIGHT0, GL_AMBIENT, none);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    const raster::Rgba8 col = m.colors.empty() ? raster::Rgba8{200, 200, 200, 255} : m.colors[0];
    const float mat[4] = {col.r / 255.0f, col.g / 255.0f, col.b / 255.0f, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, mat);
    glShadeModel(GL_SMOOTH);
    glDisableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, xyz.data());
    glNormalPointer(GL_FLOAT, 0, normal.data());
    std::vector<double> ms;
    for (int r = 0; r < runs; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      glClearColor(0, 0, 0, 1);
      glClearDepth(1);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(index.size()), GL_UNSIGNED_INT, index.data());
      glFinish();
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    std::printf("%s %.3f\n", kind, ms[ms.size() / 2]);
    glDisableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
  }
  OSMesaDestroyContext(ctx);
}
