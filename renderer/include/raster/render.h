// Render: executes a RenderPlan over a Scene and returns the finished Image.
#pragma once

#include "raster/image.h"
#include "raster/plan.h"
#include "raster/scene.h"

namespace raster {

/// Draws `scene` exactly as `plan` says. The plan must have been made from this scene.
/// Output is the same bytes for any plan.threads.
Image render(const Scene& scene, const RenderPlan& plan);

/// Convenience: plan with default options, then render.
Image render(const Scene& scene, const Limits& limits = {});

}  // namespace raster
