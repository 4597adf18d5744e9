// Geometry: Scene + RenderPlan -> Setup (setup.h). 2D points and 3D meshes (transformed, lit per face,
// clipped in homogeneous space, projected) become snapped screen-space vertices, which setup turns into one
// record per triangle or line. Triangle vertices are snapped to 1/256 px; line endpoints become the pixels
// that contain them. Nothing here touches pixels and nothing is approximated: geometry far outside the
// image takes the exact wide records instead of being clipped in floating point.
#pragma once

#include "base/stop.h"
#include "raster/plan.h"
#include "raster/scene.h"
#include "setup/setup.h"

namespace raster::detail {

/// Sets up the plan's draws, in scene order. Stops early, with the setup incomplete, once `meter` says
/// the render must stop (a record costs StopMeter::kPrimitiveWork).
Setup build_setup(const Scene& scene, const RenderPlan& plan, StopMeter& meter);

/// The 3D part (geometry3d.cpp): a mesh through the plan's camera into triangle and line records, clipped
/// in homogeneous space (near, far and a guard band) so that w > 0 everywhere and every snapped coordinate
/// stays in the fast range.
void add_mesh(const Mesh& mesh, const DrawPlan& draw, const RenderPlan& plan, Setup& setup, StopMeter& meter);

}  // namespace raster::detail
