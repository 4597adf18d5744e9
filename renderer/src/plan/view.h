// View: the scene's camera, with whatever it leaves out fitted to the 3D content -> ViewPlan (eye, target,
// up, near and far, world_to_clip). The view's lights are placed by plan/light.h.
#pragma once

#include <vector>

#include "raster/plan.h"
#include "raster/scene.h"

namespace raster::detail {

/// The camera's orthonormal basis in world space: the image's right, its up, and the view direction.
struct ViewBasis {
  Vec3 side;     ///< unit, world: the image's x (right)
  Vec3 up;       ///< unit, world: the image's up (y up), side x forward
  Vec3 forward;  ///< unit, world: from the eye toward the target
};

/// Fits the camera to the content, checks it has a view direction and an up (SceneError(invalid) naming
/// the camera field otherwise), builds the matrices and places the lights. `aspect`: width / height.
ViewPlan resolve_view(const Scene& scene, double aspect);

}  // namespace raster::detail
