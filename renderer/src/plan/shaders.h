// The plan's shader primitives: each program compiled (or found in the caller's cache), its rectangle
// clipped to the image, and every uniform it reads given its bits, ShaderToy's from the primitive's fields
// and the program's own from the scene's "uniforms", checked against what the program declares.
#pragma once

#include <cstdint>

#include "raster/plan.h"
#include "raster/scene.h"

namespace raster::detail {

/// Plans scene primitive `index`, a shader: appends its ShaderPlan to `out.shaders` and points `draw` at
/// it. False when its rectangle misses the image (it is culled). Throws SceneError(shader) when the program
/// does not compile and SceneError(invalid) for uniforms it does not declare or cannot take.
bool plan_shader(const Scene& scene, std::uint32_t index, const Limits& limits, ShaderCache* cache,
                 RenderPlan& out, DrawPlan& draw);

/// Bytes of the mipmaps of a channel image (raw bytes averaged, as glGenerateMipmap does for RGBA8).
std::int64_t channel_mip_bytes(int width, int height);

}  // namespace raster::detail
