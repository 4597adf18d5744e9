// View: the scene's camera, with whatever it leaves out fitted to the 3D content -> ViewPlan (eye, target,
// up, near and far, world_to_clip), and the scene's lights placed in world space for that view.
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

/// The lights (the scene's, or default_lights() when it has none) in world space for a camera at `eye`
/// with `basis`: camera-space directions and positions turned with the view, colour x intensity folded.
std::vector<LightPlan> place_lights(const std::vector<Light>& lights, const Vec3& eye,
                                    const ViewBasis& basis);

}  // namespace raster::detail
