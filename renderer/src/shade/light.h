// Light: a surface's unit normal and world position + the view's resolved lights (ViewPlan::lights) -> the
// Lambert factor per colour channel. The one lighting routine, written over lanes (lanes.h): the triangle
// shader calls it for eight pixels at a time (smooth shading), and geometry for one face at a time (flat
// shading), so a face lit either way is lit by the same arithmetic.
#pragma once

#include <span>
#include <vector>

#include "raster/plan.h"
#include "shade/lanes.h"

namespace raster::detail {

/// The view's lights as shading reads them: floats, ambient terms summed once, and the lights that depend on
/// the surface (directional, point) in the scene's order.
struct LightRig {
  struct Source {
    LightKind kind = LightKind::directional;  ///< directional or point
    float to_light[3] = {};                   ///< directional: unit world vector toward the light
    float position[3] = {};                   ///< point: world position
    float rgb[3] = {};                        ///< colour x intensity per channel, >= 0
  };
  float ambient[3] = {0, 0, 0};  ///< the sum of the ambient lights' colour x intensity
  std::vector<Source> sources;
  bool any_point = false;  ///< some source is a point light: shading needs the world position

  static LightRig of(std::span<const LightPlan> lights) {
    LightRig rig;
    double ambient[3] = {0, 0, 0};
    for (const LightPlan& l : lights) {
      if (l.kind == LightKind::ambient) {
        for (int c = 0; c < 3; ++c) ambient[c] += l.rgb[c];
        continue;
      }
      Source s;
      s.kind = l.kind;
      const double to[3] = {l.to_light.x, l.to_light.y, l.to_light.z},
                   at[3] = {l.position.x, l.position.y, l.position.z};
      for (int c = 0; c < 3; ++c)
        s.to_light[c] = static_cast<float>(to[c]), s.position[c] = static_cast<float>(at[c]),
        s.rgb[c] = static_cast<float>(l.rgb[c]);
      rig.any_point |= l.kind == LightKind::point;
      rig.sources.push_back(s);
    }
    for (int c = 0; c < 3; ++c) rig.ambient[c] = static_cast<float>(ambient[c]);
    return rig;
  }
};

/// Lambert under `rig` (scene.h: Light): `out` = ambient + the sum over sources of colour x intensity x
/// max(0, n . toward the light), for the unit normal n of the side seen at world point p (read only when
/// rig.any_point); a point at the lamp itself is lit fully. F is one lane (float) or eight (FloatLanes);
/// the first `channels` of out are computed (1 for grey images, whose lights are grey, else 3).
template <int channels, class F>
[[gnu::always_inline]] inline void light_lanes(const LightRig& rig, const F (&n)[3], const F (&p)[3],
                                               F (&out)[3]) {
  for (int c = 0; c < channels; ++c) out[c] = F{} + rig.ambient[c];
  for (const LightRig::Source& s : rig.sources) {
    F f;
    if (s.kind == LightKind::directional) {
      f = n[0] * s.to_light[0] + n[1] * s.to_light[1] + n[2] * s.to_light[2];
      f = f > 0.0f ? f : F{};  // also NaN
    } else {
      const F d[3] = {s.position[0] - p[0], s.position[1] - p[1], s.position[2] - p[2]};
      F len = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      sqrt_lanes(len);
      const F cosine = (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / len;
      f = cosine > 0.0f ? cosine : F{};
      f = len > 0.0f ? f : F{} + 1.0f;
    }
    for (int c = 0; c < channels; ++c) out[c] += s.rgb[c] * f;
  }
}

}  // namespace raster::detail
