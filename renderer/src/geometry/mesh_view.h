// What the 3D geometry's two halves share (geometry3d.cpp: triangles; geometry3d_lines.cpp: lines, feature
// edges and points): the clip-space vertex and its clipping against the six planes, the viewport, and a mesh
// seen through the camera, every vertex projected once.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "base/memory.h"
#include "base/parallel.h"
#include "base/srgb.h"  // to_byte: a line's endpoint colours become bytes as pixels do
#include "base/vecmath.h"
#include "geometry/geometry.h"
#include "setup/batch.h"

namespace raster::detail::mesh3d {

/// The one vertex record of the 3D path: clip-space position plus the values of its primitive's varyings,
/// laid out as a SetupVertex's (raster/plan.h: VaryingLayout), so clipping interpolates them all with one
/// routine and a projected vertex takes them as they are.
struct ClipVertex {
  double x = 0, y = 0, z = 0, w = 0;  ///< clip space (see ViewPlan)
  float values[VaryingLayout::kMaxFloats] =
      {};  ///< at VaryingLayout::vertex_offset; depth and 1/w not yet written
};

/// a + (b - a) t, position and the first `floats` values (VaryingLayout::clipped_floats).
inline ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t, int floats) {
  ClipVertex r;
  r.x = a.x + (b.x - a.x) * t, r.y = a.y + (b.y - a.y) * t, r.z = a.z + (b.z - a.z) * t,
  r.w = a.w + (b.w - a.w) * t;
  for (int k = 0; k < floats; ++k)
    r.values[k] = static_cast<float>(a.values[k] + (b.values[k] - a.values[k]) * t);
  return r;
}

/// Six planes, each a linear function of (x, y, z, w) that is >= 0 inside: near (z <= w), far (z >= 0) and
/// the guard band |x|, |y| <= g w, which keeps snapped coordinates within +-(image + 8192 px).
struct Planes {
  double gx = 1, gy = 1;
  double distance(const ClipVertex& v, int plane) const {
    switch (plane) {
      case 0:
        return v.w - v.z;
      case 1:
        return v.z;
      case 2:
        return gx * v.w + v.x;
      case 3:
        return gx * v.w - v.x;
      case 4:
        return gy * v.w + v.y;
      default:
        return gy * v.w - v.y;
    }
  }
};
inline constexpr int kPlaneCount = 6;
inline constexpr double kGuardPx = 8192;

// The crossing of segment a-b with a plane, computed from the endpoints in a canonical order so that two
// triangles sharing the edge get bit-identical vertices and the edge stays watertight.
inline ClipVertex intersect(const ClipVertex& a, const ClipVertex& b, int plane, const Planes& planes,
                            int floats) {
  const bool swap = std::tie(b.x, b.y, b.z, b.w) < std::tie(a.x, a.y, a.z, a.w);
  const ClipVertex& p = swap ? b : a;
  const ClipVertex& q = swap ? a : b;
  const double dp = planes.distance(p, plane), dq = planes.distance(q, plane);
  return lerp(p, q, dp / (dp - dq), floats);
}

// Sutherland-Hodgman in homogeneous space; returns the vertex count of the clipped polygon (0 if gone).
inline int clip_polygon(std::array<ClipVertex, 9>& poly, int n, const Planes& planes, int floats) {
  std::array<ClipVertex, 9> out;
  for (int plane = 0; plane < kPlaneCount && n >= 3; ++plane) {
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const ClipVertex& a = poly[i];
      const ClipVertex& b = poly[(i + 1) % n];
      const bool a_in = planes.distance(a, plane) >= 0, b_in = planes.distance(b, plane) >= 0;
      if (a_in) out[m++] = a;
      if (a_in != b_in) out[m++] = intersect(a, b, plane, planes, floats);
    }
    poly = out;
    n = m;
  }
  return n >= 3 ? n : 0;
}

// The same for a segment (parametric): false when nothing is left.
inline bool clip_segment(ClipVertex& a, ClipVertex& b, const Planes& planes, int floats) {
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    const double da = planes.distance(a, plane), db = planes.distance(b, plane);
    if (da < 0 && db < 0) return false;
    if (da < 0)
      a = intersect(a, b, plane, planes, floats);
    else if (db < 0)
      b = intersect(a, b, plane, planes, floats);
  }
  return true;
}

struct Viewport {
  double width, height;
  // Perspective divide and viewport: NDC x right, y up -> pixels x right, y down.
  void project(const ClipVertex& v, double& sx, double& sy, double& depth, double& inv_w) const {
    inv_w = 1.0 / v.w;  // clipping guarantees w > 0
    sx = (v.x * inv_w + 1) * 0.5 * width;
    sy = (1 - v.y * inv_w) * 0.5 * height;
    depth = std::clamp(v.z * inv_w, 0.0, 1.0);
  }
};

// Clipping keeps every vertex inside the guard band in exact arithmetic. In doubles, coordinates near 1e30
// cancel catastrophically and a clipped vertex can land anywhere, even at w = 0 (found by the fuzzer: a
// NaN reached an integer conversion). Such a vertex has no trustworthy position: its primitive is dropped.
inline bool in_guard_band(double sx, double sy, double inv_w) {
  return std::isfinite(inv_w) && inv_w > 0 && std::fabs(sx) <= kFastRangePx && std::fabs(sy) <= kFastRangePx;
}

inline Rgba8 to_rgba8(const float* c) {
  return {to_byte(c[0]), to_byte(c[1]), to_byte(c[2]), to_byte(c[3])};
}

inline void put_color(float* to, Rgba8 c) {
  to[0] = c.r, to[1] = c.g, to[2] = c.b, to[3] = c.a;
}

/// Where the viewport puts a projected vertex's depth and 1 / w, for the rows `varyings` has.
inline void put_projection(const VaryingLayout& varyings, SetupVertex& v, double depth, double inv_w) {
  if (varyings.has(Varying::depth)) *v.at(varyings, Varying::depth) = static_cast<float>(depth);
  if (varyings.has(Varying::inv_w)) *v.at(varyings, Varying::inv_w) = static_cast<float>(inv_w);
}

/// Meshes with at least twice this many vertices (triangles) have them transformed (set up, and their
/// normals computed) on every render thread: vertices in pieces of this size, triangles in four pieces a
/// thread of at least this size. Smaller ones stay on the calling thread. 1024: the Stanford bunny (3,674
/// triangles) renders 6% faster at 2 threads split than whole (1.33-1.35 against 1.42 ms, plan + render);
/// a hand-off costs far less than a thousand triangles' setup.
inline constexpr std::size_t kPiece = 1024;

/// A mesh through the camera: every vertex once (which clip planes it is outside of, its world position,
/// and inside all of them its projected, snapped screen position, so a triangle that needs no clipping
/// costs no projection), and what the triangles and lines share.
struct MeshView {
  const Mesh& mesh;
  const RenderPlan& plan;
  Planes planes;
  Viewport viewport;
  Mat4 model_to_clip;
  // Per vertex, each written once before it is read:
  PodArray<std::uint8_t>
      outside;  ///< bit p: outside plane p; 0x40: inside but not projectable; 0x80: not finite
  PodArray<ScreenVertex> screen;  ///< where outside == 0; x is kNoScreen elsewhere
  /// The mesh is in world space already (its transform the identity, as a model's is): world_at reads its
  /// positions, and no world array is made (24 bytes a vertex, written and read again).
  bool identity;
  PodArray<Vec3> world;  ///< world positions, under a transform (empty under the identity)

  MeshView(const Mesh& m, const RenderPlan& p)
      : mesh(m),
        plan(p),
        planes{1 + 2 * kGuardPx / p.width, 1 + 2 * kGuardPx / p.height},
        viewport{static_cast<double>(p.width), static_cast<double>(p.height)},
        model_to_clip(p.view.world_to_clip * m.transform),
        identity(m.transform == Mat4{}) {
    outside.resize_uninitialized(m.positions.size()), screen.resize_uninitialized(m.positions.size());
    if (!identity) world.resize_uninitialized(m.positions.size());
  }

  /// Vertex i's world position: under the identity its position widened, a zero of either sign as +0 (the
  /// bits transform_point gives: x + 0 y + 0 z + 0).
  Vec3 world_at(std::size_t i) const {
    if (!identity) return world[i];
    const Vec3f& p = mesh.positions[i];
    return {p.x + 0.0, p.y + 0.0, p.z + 0.0};
  }

  /// Every vertex, in pieces on the render's threads (each writes its own vertices). False when stopped.
  bool project(StopMeter& meter) {
    const std::size_t nv = mesh.positions.size();
    const std::size_t pieces = (nv + kPiece - 1) / kPiece;
    parallel_for(nv >= 2 * kPiece ? plan.threads : 1, pieces, meter.stop(),
                 [&](std::size_t piece, StopMeter& own, int) {
                   const std::size_t end = std::min(nv, (piece + 1) * kPiece);
                   for (std::size_t i = piece * kPiece; i < end; ++i) {
                     if (own.add(StopMeter::kRowWork)) return;  // a model can have millions of vertices
                     project_vertex(i);
                   }
                 });
    return !meter.check();
  }

  void project_vertex(std::size_t i) {
    if (!identity) world[i] = transform_point(mesh.transform, mesh.positions[i]);
    const Vec4 c = transform(model_to_clip, mesh.positions[i]);
    screen[i] = {kNoScreen, 0, 0, 0};  // until it is projected (the batches read every vertex's)
    if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w))) {
      outside[i] = 0x80;
      return;
    }
    const ClipVertex v{c.x, c.y, c.z, c.w, {}};
    std::uint8_t bits = 0;
    for (int plane = 0; plane < kPlaneCount; ++plane)
      bits |= (planes.distance(v, plane) < 0 ? 1 : 0) << plane;
    outside[i] = bits;
    if (bits) return;
    double sx, sy, depth, inv_w;
    viewport.project(v, sx, sy, depth, inv_w);
    if (!in_guard_band(sx, sy, inv_w)) {
      outside[i] = 0x40;  // inside every plane yet not projectable: dropped like a clipped one would be
      return;
    }
    screen[i] = {static_cast<std::int32_t>(snap(sx)), static_cast<std::int32_t>(snap(sy)),
                 static_cast<float>(depth), static_cast<float>(inv_w)};
  }

  Rgba8 vertex_color(std::uint32_t vertex) const {
    return mesh.colors.size() == 1 ? mesh.colors[0] : mesh.colors[vertex];
  }
  Rgba8 color_at(std::size_t triangle, std::uint32_t vertex) const {
    return mesh.face_colors.empty() ? vertex_color(vertex) : mesh.face_colors[triangle];
  }
  /// The vertex in clip space (computed again: only clipped primitives need it), with colour `c` in the
  /// place `varyings` gives it.
  ClipVertex clip_vertex(std::uint32_t i, const VaryingLayout& varyings, Rgba8 c) const {
    const Vec4 p = transform(model_to_clip, mesh.positions[i]);
    ClipVertex v{p.x, p.y, p.z, p.w, {}};
    put_color(v.values + varyings.vertex_offset[static_cast<int>(Varying::color)], c);
    return v;
  }
};

/// The mesh's segments (and, for wireframes, every triangle edge), its feature edges and its points, through
/// the camera into records (geometry3d_lines.cpp).
void add_lines(const MeshView& view, const PrimitivePlan& line_mode, Setup& setup, StopMeter& meter);
void add_edges(const MeshView& view, const PrimitivePlan& edge_mode, Setup& setup, StopMeter& meter);
void add_points(const MeshView& view, const PrimitivePlan& point_mode, Setup& setup, StopMeter& meter);

}  // namespace raster::detail::mesh3d
