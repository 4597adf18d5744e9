// Light: a surface's unit normal and world position + the view's resolved lights (ViewPlan::lights) -> the
// Lambert factor per colour channel. Its own header because two stages light: geometry once per face (flat
// shading), the triangle shader once per pixel (smooth shading).
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

#include "raster/plan.h"

namespace raster::detail {

/// Lambert under the view's lights (scene.h: Light): `out` = the sum over lights of colour x intensity x
/// (ambient: 1; directional, point: max(0, n . toward the light)), for the unit normal n of the side seen at
/// world point p. Used per face by geometry (flat lighting) and per pixel by the triangle shader (shade.h).
inline void light_at(std::span<const LightPlan> lights, const double (&n)[3], const double (&p)[3],
                     double (&out)[3]) {
  out[0] = out[1] = out[2] = 0;
  for (const LightPlan& l : lights) {
    double f = 1;
    if (l.kind == LightKind::directional) {
      f = std::max(0.0, n[0] * l.to_light.x + n[1] * l.to_light.y + n[2] * l.to_light.z);
    } else if (l.kind == LightKind::point) {
      const double d[3] = {l.position.x - p[0], l.position.y - p[1], l.position.z - p[2]};
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      f = len > 0 ? std::max(0.0, (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / len) : 1;  // at the lamp: lit
    }
    for (int c = 0; c < 3; ++c) out[c] += l.rgb[c] * f;
  }
}

}  // namespace raster::detail
