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

}  // namespace raster::detail
