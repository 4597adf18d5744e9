#include "geometry/normals.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/parallel.h"

namespace raster::detail {
namespace {

// acos to within 2e-8 rad (Abramowitz & Stegun 4.4.46), a square root and a polynomial: three per triangle
// were the costliest part of computing a model's normals (libm's acos), and an error this small is below
// what the float normals the records carry can hold (6e-8 relative).
double arc_cosine(double x) {
  const double a = std::fabs(x);
  const double p =
      1.5707963050 +
      a * (-0.2145988016 +
           a * (0.0889789874 +
                a * (-0.0501743046 +
                     a * (0.0308918810 + a * (-0.0170881256 + a * (0.0066700901 + a * -0.0012624911))))));
  const double r = std::sqrt(1 - a) * p;
  return x < 0 ? std::numbers::pi - r : r;
}

}  // namespace

PodArray<Vec3> vertex_normals(const Mesh& mesh, std::span<const Vec3> world, int threads, StopMeter& meter) {
  const std::size_t nv = world.size();
  PodArray<Vec3> normals;
  normals.resize_uninitialized(nv);
  const std::size_t pieces = static_cast<std::size_t>(std::max(threads, 1));
  parallel_for(threads, pieces, meter.stop(), [&](std::size_t piece, StopMeter& own, int) {
    const std::uint32_t v0 = static_cast<std::uint32_t>(nv * piece / pieces),
                        v1 = static_cast<std::uint32_t>(nv * (piece + 1) / pieces);
    std::fill(normals.data() + v0, normals.data() + v1, Vec3{});
    auto mine = [&](std::uint32_t v) { return v >= v0 && v < v1; };
    for (const auto& t : mesh.triangles) {
      if (own.add(StopMeter::kRowWork)) return;  // the caller sees meter.stopped() and draws nothing
      const bool corner[3] = {mine(t[0]), mine(t[1]), mine(t[2])};
      if (!(corner[0] || corner[1] || corner[2])) continue;
      const Vec3 p[3] = {world[t[0]], world[t[1]], world[t[2]]};
      const Vec3 face = normalize(cross(p[1] - p[0], p[2] - p[0]));
      // Edge k runs from vertex k to the next; each length is taken once (a zero-length edge: angle pi/2,
      // as for a zero vector's direction).
      const Vec3 edge[3] = {p[1] - p[0], p[2] - p[1], p[0] - p[2]};
      const double len[3] = {length(edge[0]), length(edge[1]), length(edge[2])};
      for (int k = 0; k < 3; ++k) {
        if (!corner[k]) continue;
        const int prev =
            (k + 2) % 3;  // the corner at vertex k is between edge k and the reversed edge before it
        const double norms = len[k] * len[prev];
        const double cosine = norms > 0 && std::isfinite(norms) ? -dot(edge[k], edge[prev]) / norms : 0.0;
        const double angle = arc_cosine(std::clamp(cosine, -1.0, 1.0));
        normals[t[k]] = normals[t[k]] + face * angle;
      }
    }
    for (std::uint32_t v = v0; v < v1; ++v) normals[v] = normalize(normals[v]);
  });
  meter.check();
  return normals;
}

}  // namespace raster::detail
