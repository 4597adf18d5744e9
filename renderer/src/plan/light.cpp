#include "plan/light.h"
#include "base/vecmath.h"

namespace raster::detail {

std::vector<LightPlan> place_lights(const std::vector<Light>& scene_lights, const Vec3& eye,
                                    const ViewBasis& basis) {
  // A camera-space vector (x right, y up, z toward the viewer) is the same combination of the view's own
  // axes.
  auto from_camera = [&](const Vec3& c) { return basis.side * c.x + basis.up * c.y - basis.forward * c.z; };
  std::vector<LightPlan> out;
  for (const Light& light : scene_lights.empty() ? default_lights() : scene_lights) {
    LightPlan l;
    l.kind = light.kind;
    if (light.kind == LightKind::directional) {
      const Vec3 travel = normalize(light.camera_space ? from_camera(light.direction) : light.direction);
      l.to_light = travel * -1.0;
    }
    if (light.kind == LightKind::point)
      l.position = light.camera_space ? eye + from_camera(light.position) : light.position;
    l.rgb[0] = light.color.x * light.intensity, l.rgb[1] = light.color.y * light.intensity;
    l.rgb[2] = light.color.z * light.intensity;
    out.push_back(l);
  }
  return out;
}

}  // namespace raster::detail
