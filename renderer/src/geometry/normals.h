// Normals: a mesh's smooth-shading normals when it brings none, computed once per vertex in world space.
#pragma once

#include <span>

#include "base/memory.h"
#include "base/stop.h"
#include "base/vecmath.h"
#include "raster/plan.h"
#include "raster/scene.h"

namespace raster::detail {

/// Angle-weighted vertex normals in world space (Thuermer & Wuethrich): each face adds its unit normal times
/// the corner angle, so a vertex's normal does not depend on how its neighbourhood is triangulated.
///
/// On several threads each takes a range of the vertices and goes through all the triangles, adding only to
/// its own vertices: every vertex still sums its faces in triangle order, so the normals are the same bits
/// for any thread count (a triangle whose corners lie in two ranges is measured twice). Triangles are
/// measured four at a time, on `simd`'s instruction set, with the bits of one at a time.
/// `world`: the mesh's world positions, one per position; empty when the mesh is in world space already (its
/// transform the identity), whose positions are then read as MeshView::world_at reads them.
/// `needed`: null for every vertex's normal; else a byte per vertex, and only the vertices marked non-zero
/// get theirs (the others are zero), each the same bits, and only the triangles with such a corner are
/// measured.
PodArray<Vec3> vertex_normals(const Mesh& mesh, std::span<const Vec3> world, int threads, Simd simd,
                              StopMeter& meter, const std::uint8_t* needed = nullptr);

/// A creased mesh's corners whose normal is not their vertex's (Mesh::crease_deg): at a vertex where some
/// face turns further than the crease from the others, the faces around it are split into the groups that
/// edges of at most crease_deg join (VTK's normals filter: a sharp edge splits), and each corner takes its
/// group's angle-weighted normal. Every other vertex keeps vertex_normals' normal, bit for bit.
struct CornerNormals {
  static constexpr std::uint32_t kSmooth = 0xffffffffu;
  PodArray<std::uint32_t> slot;   ///< per vertex: kSmooth, or its index into `first`; empty: none split
  PodArray<std::uint32_t> first;  ///< per split vertex, its first entry; and one past the last vertex's
  PodArray<std::uint32_t>
      triangle;            ///< per entry: a triangle with a corner at the vertex, in increasing order
  PodArray<Vec3f> normal;  ///< per entry: that corner's normal (world, unit)
  bool empty() const { return slot.empty(); }
  /// The normal of triangle `t`'s corner at vertex `v`, or null where v keeps its vertex normal.
  const Vec3f* at(std::uint32_t v, std::uint32_t t) const;
};

/// The split corners of `mesh` (its crease_deg below 180) for the vertex normals `normals` (vertex_normals'
/// result for the same `world` and `needed`): found in a pass over the triangles on `threads`, a vertex
/// split only where a face around it lies more than half the crease from its normal (so that no two do
/// within it otherwise), its faces grouped in O(d log d) for a vertex of d faces. The arrays are asked of
/// the render's budget first (a refusal stops the render; the result is then empty).
CornerNormals crease_normals(const Mesh& mesh, std::span<const Vec3> world, const PodArray<Vec3>& normals,
                             int threads, StopMeter& meter, const std::uint8_t* needed = nullptr);

}  // namespace raster::detail
