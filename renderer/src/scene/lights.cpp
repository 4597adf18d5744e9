// The lights a scene gets when it names none (default_lights), and the one-light form of the format
// ("light": {"ambient": a, "direction": d}) as the lights it stands for (single_light). Scene data, not
// checks: the plan places them for the view (plan/light.cpp), validate() checks them as any others.
#include <vector>

#include "raster/scene.h"

namespace raster {
namespace {

// A light of `kind` and `intensity`; camera-space directional lights travel `direction`.
Light make_light(LightKind kind, double intensity, bool camera_space = false, Vec3 direction = {0, 0, -1}) {
  Light l;
  l.kind = kind, l.intensity = intensity, l.camera_space = camera_space, l.direction = direction;
  return l;
}

}  // namespace

std::vector<Light> default_lights() {
  return {
      make_light(LightKind::ambient, 0.35),
      // From the viewer's upper left, as a photographer's key: travels right, down and away from the viewer.
      make_light(LightKind::directional, 0.45, true, {1, -1, -1}),
      // Along the view direction: every face seen gets some light, so none is left black.
      make_light(LightKind::directional, 0.25, true, {0, 0, -1}),
  };
}

std::vector<Light> single_light(double ambient, const Vec3* direction) {
  if (direction)
    return {make_light(LightKind::ambient, ambient),
            make_light(LightKind::directional, 1 - ambient, false, *direction)};
  return {make_light(LightKind::ambient, ambient),
          make_light(LightKind::directional, 1 - ambient, true)};  // the headlight
}

}  // namespace raster
