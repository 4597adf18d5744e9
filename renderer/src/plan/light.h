// Light, the one lighting module: the scene's lights placed in world space for the view (place_lights,
// light.cpp, giving ViewPlan::lights), the same lights as shading reads them (LightRig, which the plan's
// draw calls carry), and their evaluation: Lambert over lanes (base/lanes.h), called by geometry once per
// face (light_face, flat shading) and by shade for eight pixels at a time (smooth shading), so a face lit
// either way is lit by the same arithmetic; specular materials (scene.h: Material) add specular_lanes, per
// pixel only, taken by the draw calls whose plan says so.
#pragma once

#include <span>
#include <vector>

#include "base/lanes.h"
#include "base/mip_chain.h"
#include "plan/view.h"
#include "raster/plan.h"
#include "raster/scene.h"

namespace raster::detail {

/// The lights (the scene's, or default_lights() when it has none) in world space for a camera at `eye`
/// with `basis`: camera-space directions and positions turned with the view, colour x intensity folded.
std::vector<LightPlan> place_lights(const std::vector<Light>& lights, const Vec3& eye,
                                    const ViewBasis& basis);

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

/// Flat shading: the Lambert factor per colour channel of a face whose unit world normal `n` points to the
/// side seen, lit at its centroid `centre` (world).
inline void light_face(const LightRig& rig, const Vec3& n, const Vec3& centre, float (&out)[3]) {
  const float normal[3] = {static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z)};
  const float at[3] = {static_cast<float>(centre.x), static_cast<float>(centre.y),
                       static_cast<float>(centre.z)};
  light_lanes<3>(rig, normal, at, out);
}

/// A specular material (scene.h: Material) as shading reads it, with the view it is seen from: one per draw
/// call, so that which BRDF a pixel takes is decided per draw, never per pixel.
struct Specular {
  Material::Model model = Material::Model::lambert;  ///< metallic_roughness or blinn_phong
  float metallic = 1, roughness = 1;                 ///< metallic_roughness: factors, 0..1
  const MipChain* metallic_roughness = nullptr;      ///< its texture (B metallic, G roughness), or none
  float specular[3] = {};                            ///< blinn_phong: Ks per channel, 0..1
  int shininess = 1;                                 ///< blinn_phong: Ns rounded, 0..1000
  bool orthographic = false;                         ///< the view direction is the same everywhere:
  float toward_eye[3] = {};                          ///< orthographic: unit world vector toward the eye
  float eye[3] = {};                                 ///< perspective: the eye's world position
};

/// x^n for a whole n >= 0 by squaring: multiplications only, so every lane width rounds alike (a pow through
/// exp and log would be a library call whose vector and scalar forms may differ).
/// (Values in and out by reference: eight lanes cannot be passed by value between AVX and other code.)
template <class F>
[[gnu::always_inline]] inline void pow_whole(const F& base, int n, F& out) {
  F x = base;
  out = F{} + 1.0f;
  for (; n > 0; n >>= 1, x *= x)
    if (n & 1) out *= x;
}

/// The unit vector of `d` in place, and its length before in `len` (0 leaves it zero, not NaN).
template <class F>
[[gnu::always_inline]] inline void normalize_lanes(F (&d)[3], F& len) {
  len = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  sqrt_lanes(len);
  const F scale = len > 0.0f ? 1.0f / len : F{};
  for (F& c : d) c *= scale;
}

/// A specular surface's colour under `rig`: `rgb` (0..255, sRGB-encoded, the base colour with its texture)
/// in, lit colour (0..255, unclamped) out, for the unit normal n of the side seen at world point p, with the
/// material's metallic and roughness at the pixel (`mr`: factors times the texture's, metallic_roughness
/// only). metallic_roughness is glTF 2.0's appendix B BRDF times pi (the lights' convention, scene.h: Light):
///   ambient x (c_diff + F0) + sum over lights of light x (n.l) x ((1 - F) c_diff + pi F D V),
/// c_diff = base (1 - metallic), F0 = 0.04 (1 - metallic) + base metallic, F Schlick's Fresnel at v.h,
/// D Trowbridge-Reitz (GGX) and V the height-correlated Smith visibility at alpha = roughness^2.
/// blinn_phong is Lambert (light_lanes) plus sum over lights facing the surface of light x Ks x (n.h)^Ns.
template <int channels, class F>
[[gnu::always_inline]] inline void specular_lanes(const LightRig& rig, const Specular& look, const F (&n)[3],
                                                  const F (&p)[3], const F (&mr)[2], F (&rgb)[4]) {
  constexpr float kPi = 3.14159265358979f;
  F v[3];
  if (look.orthographic) {
    for (int c = 0; c < 3; ++c) v[c] = F{} + look.toward_eye[c];
  } else {
    for (int c = 0; c < 3; ++c) v[c] = look.eye[c] - p[c];
    F len;
    normalize_lanes(v, len);
  }
  // metallic_roughness: the base colour in 0..1, and the light each channel reflects summed into `out`.
  F base[3], out[3];
  for (int c = 0; c < channels; ++c) base[c] = rgb[c] * (1.0f / 255.0f);
  const bool pbr = look.model == Material::Model::metallic_roughness;
  F c_diff[3] = {}, f0[3] = {}, alpha2{}, n_v{};
  if (pbr) {
    const F metallic = mr[0], rough = mr[1] > 0.05f ? mr[1] : F{} + 0.05f;
    const F alpha = rough * rough;
    alpha2 = alpha * alpha;
    for (int c = 0; c < channels; ++c) {
      c_diff[c] = base[c] * (1.0f - metallic);
      f0[c] = 0.04f * (1.0f - metallic) + base[c] * metallic;
      out[c] = rig.ambient[c] * (c_diff[c] + f0[c]);
    }
    n_v = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
    n_v = n_v > 1e-4f ? n_v : F{} + 1e-4f;  // a normal turned from the eye (interpolated): grazing
  } else {  // Lambert as light_lanes gives it (and as the colour is multiplied by it without materials)
    light_lanes<channels>(rig, n, p, out);
    for (int c = 0; c < channels; ++c) out[c] *= rgb[c];
  }
  F extra[3] = {};  // blinn_phong: the lobes' sum, 0..1
  for (const LightRig::Source& s : rig.sources) {
    F l[3];
    if (s.kind == LightKind::directional) {
      for (int c = 0; c < 3; ++c) l[c] = F{} + s.to_light[c];
    } else {
      for (int c = 0; c < 3; ++c) l[c] = s.position[c] - p[c];
      F len;
      normalize_lanes(l, len);
      for (int c = 0; c < 3; ++c) l[c] = len > 0.0f ? l[c] : n[c];  // at the lamp: lit head-on
    }
    F n_l = n[0] * l[0] + n[1] * l[1] + n[2] * l[2];
    n_l = n_l > 0.0f ? n_l : F{};  // also NaN
    F h[3] = {l[0] + v[0], l[1] + v[1], l[2] + v[2]};
    F h_len;
    normalize_lanes(h, h_len);
    F n_h = n[0] * h[0] + n[1] * h[1] + n[2] * h[2];
    n_h = n_h > 0.0f ? n_h : F{};
    if (!pbr) {
      F lobe;
      pow_whole(n_h, look.shininess, lobe);
      const F facing = n_l > 0.0f ? lobe : F{};
      for (int c = 0; c < channels; ++c) extra[c] += s.rgb[c] * look.specular[c] * facing;
      continue;
    }
    F v_h = v[0] * h[0] + v[1] * h[1] + v[2] * h[2];
    v_h = v_h > 0.0f ? v_h : F{};
    const F m = 1.0f - v_h, m2 = m * m, schlick = m2 * m2 * m;
    const F t = n_h * n_h * (alpha2 - 1.0f) + 1.0f;
    const F d = alpha2 / (kPi * t * t);
    F root_l = alpha2 + (1.0f - alpha2) * n_l * n_l, root_v = alpha2 + (1.0f - alpha2) * n_v * n_v;
    sqrt_lanes(root_l), sqrt_lanes(root_v);
    const F vis = 1.0f / ((n_l + root_l) * (n_v + root_v));
    const F spec = kPi * d * vis;
    for (int c = 0; c < channels; ++c) {
      const F fresnel = f0[c] + (1.0f - f0[c]) * schlick;
      out[c] += s.rgb[c] * n_l * ((1.0f - fresnel) * c_diff[c] + fresnel * spec);
    }
  }
  for (int c = 0; c < channels; ++c) rgb[c] = pbr ? out[c] * 255.0f : out[c] + extra[c] * 255.0f;
}

}  // namespace raster::detail
