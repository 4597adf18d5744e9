// Geometry: Scene + RenderPlan -> Setup (setup.h). 2D points and 3D meshes (transformed, lit per face,
// clipped in homogeneous space, projected) become snapped screen-space vertices, which setup turns into one
// record per triangle or line. Triangle vertices are snapped to 1/256 px; line endpoints become the pixels
// that contain them. Nothing here touches pixels and nothing is approximated: geometry far outside the
// image takes the exact wide records instead of being clipped in floating point.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "base/parallel.h"
#include "base/stop.h"
#include "raster/plan.h"
#include "raster/scene.h"
#include "setup/setup.h"

namespace raster::detail {

/// Runs `run(begin, end, part, meter)` over [0, count) (a mesh's triangles or points): small counts into the
/// current part, as 2D records are (no part per small mesh); else in pieces on every render thread, each
/// piece into a part of its own, parts in order, so the image is that of one thread. Four pieces a thread
/// (some pieces clip, some lie off-screen: threads that finish early take more), of at least `least`.
template <typename Run>
void in_parts(std::size_t count, std::size_t least, int plan_threads, Setup& setup, StopMeter& meter,
              Run&& run) {
  const int threads = count >= 2 * least ? plan_threads : 1;
  const std::size_t size = threads > 1 ? std::max(least, (count + 4 * threads - 1) / (4 * threads)) : count;
  const std::size_t pieces = count ? (count + size - 1) / size : 0;
  if (pieces <= 1) return run(0, count, setup.last_part(), meter);
  const std::size_t first = setup.parts.size();
  setup.parts.resize(first + pieces);
  parallel_for(threads, pieces, meter.stop(), [&](std::size_t piece, StopMeter& own, int) {
    // Filled on the thread's stack and moved in at the end: parts lie side by side in memory, and two threads
    // growing neighbouring ones would share the cache line of their sizes.
    Records part;
    run(piece * size, std::min(count, (piece + 1) * size), part, own);
    setup.parts[first + piece] = std::move(part);
  });
  meter.check();
  setup.parts.emplace_back();  // what follows goes after all of the pieces
}

/// The corners of the rectangle `width` pixels wide around the segment (ax, ay)-(bx, by) (butt caps), in
/// the order a + n, b + n, b - n, a - n for n the normal of half the width: how anti-aliased and wide lines
/// are drawn, in 2D and 3D. False for a segment without a direction (length 0, or too long to be finite).
inline bool segment_rectangle(double ax, double ay, double bx, double by, double width, double (&x)[4],
                              double (&y)[4]) {
  const double dx = bx - ax, dy = by - ay, len = std::hypot(dx, dy);
  if (!(len > 0) || !std::isfinite(len)) return false;
  const double half = width * 0.5, nx = -dy / len * half, ny = dx / len * half;
  x[0] = ax + nx, x[1] = bx + nx, x[2] = bx - nx, x[3] = ax - nx;
  y[0] = ay + ny, y[1] = by + ny, y[2] = by - ny, y[3] = ay - ny;
  return true;
}

/// Sets up the plan's draws, in scene order. Stops early, with the setup incomplete, once `meter` says
/// the render must stop (a record costs StopMeter::kPrimitiveWork).
Setup build_setup(const Scene& scene, const RenderPlan& plan, StopMeter& meter);

/// The 3D part (geometry3d.cpp): a mesh through the plan's camera into triangle, line and point records,
/// clipped in homogeneous space (near, far and a guard band) so that w > 0 everywhere and every snapped
/// coordinate stays in the fast range.
void add_mesh(const Mesh& mesh, const DrawPlan& draw, const RenderPlan& plan, Setup& setup, StopMeter& meter);

/// A specular mesh's draw calls (PrimitivePlan::specular), one for each (texture, material) pair its faces
/// use, by material_key.
using MaterialCalls = std::unordered_map<std::uint64_t, std::uint32_t>;

/// Triangle `t`'s pair as MaterialCalls keys it: (texture + 1) << 32 | (material + 1), -1 meaning none.
inline std::uint64_t material_key(const Mesh& mesh, std::size_t t, std::int32_t texture) {
  const std::int32_t material =
      mesh.face_materials.empty() ? (mesh.materials.empty() ? -1 : 0) : mesh.face_materials[t];
  return static_cast<std::uint64_t>(texture + 1) << 32 | static_cast<std::uint32_t>(material + 1);
}

/// Adds the calls of a specular mesh's pairs to `setup`, found in one pass over its faces (a mesh of many
/// materials and textures makes only the pairs it has), each `call` with its texture (`chains`: the mip
/// chain of each of the mesh's textures, when `textured`), its material as shading reads it and the eye.
MaterialCalls add_material_calls(const Mesh& mesh, const ViewPlan& view, bool textured,
                                 const std::vector<const MipChain*>& chains, DrawCall call, Setup& setup);

}  // namespace raster::detail
