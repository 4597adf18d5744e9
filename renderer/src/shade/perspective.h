// Perspective shading: one 3D triangle record's varyings (raster/plan.h: Varyings) + a pixel's screen-space
// barycentrics -> its colour, in floats, eight pixels at a time or one. Interpolation is perspective-correct
// (each value weighted by l_k / w_k, normalised), the interpolated normal is renormalised and flipped to the
// side seen, lit by light.h's one routine, and the texture is sampled where the record has one. Written once
// over lanes (lanes.h), so the eight-pixel path of aliased blocks and the one-pixel path of multisampled
// pixels give a pixel the same bytes.
#pragma once

#include <algorithm>
#include <cstdint>

#include "base/lanes.h"
#include "plan/light.h"
#include "raster/image.h"
#include "raster/plan.h"
#include "setup/setup.h"
#include "shade/texture.h"

namespace raster::detail {

/// What one record's pixels are coloured from, read once per record per tile: floats, per vertex.
class PerspectiveColor {
 public:
  PerspectiveColor() = default;
  /// `at[v][k]`: vertex k's value of varying v in the record, nullptr when absent (uv: also when the face has
  /// no texture); `flip` -1 for a back face; `dl_dx`, `dl_dy` the barycentrics' change per pixel right and
  /// down.
  PerspectiveColor(const DrawCall& call, const float* const (&at)[kVaryingCount][3], float flip,
                   const double (&dl_dx)[3], const double (&dl_dy)[3])
      : rig_(&call.lights), flip_(flip) {
    // Pointers into the record, not copies: a dense mesh's record covers a pixel or two, so what is set up
    // per record must cost less than a pixel's shading; the lanes broadcast from the record as cheaply.
    auto row = [&](Varying v) { return at[static_cast<int>(v)]; };
    if (call.specular.model != Material::Model::lambert) specular_ = &call.specular;
    for (int k = 0; k < 3; ++k) {
      inv_w_[k] = row(Varying::inv_w)[k];
      color_[k] = row(Varying::color)[k];
      normal_at_[k] = row(Varying::normal)[k];
      position_at_[k] = rig_->any_point || specular_ ? row(Varying::position)[k] : nullptr;
    }
    flat_color_ = call.mode.varyings.how(Varying::color) == Interpolation::flat;
    const MipChain* metal_rough = specular_ ? specular_->metallic_roughness : nullptr;
    if (const float* const* uv = row(Varying::uv); uv[0] && (call.texture || metal_rough)) {
      texture_ = call.texture;
      metal_rough_ = metal_rough;
      // Screen derivatives of u / w, v / w and 1 / w: constants of the record (exact inputs, in doubles).
      double d[6] = {};
      for (int k = 0; k < 3; ++k) {
        const double w = *inv_w_[k];
        d[0] += dl_dx[k] * w * uv[k][0], d[1] += dl_dx[k] * w * uv[k][1], d[2] += dl_dx[k] * w;
        d[3] += dl_dy[k] * w * uv[k][0], d[4] += dl_dy[k] * w * uv[k][1], d[5] += dl_dy[k] * w;
        uv_[k] = uv[k];
      }
      for (int i = 0; i < 6; ++i) uv_slopes_[i] = static_cast<float>(d[i]);
    }
  }

  /// The colour (0..255 scale, straight alpha; `colours` channels of RGB, then alpha in rgba[3]) at
  /// barycentrics `l` of the lanes in `lanes` (bit i: lane i; the others' values are not used and may be
  /// anything). F is float (one lane) or FloatLanes.
  template <int colours, class F>
  [[gnu::always_inline]] inline void shade(const F (&l)[3], unsigned lanes, F (&rgba)[4]) const {
    F q[3];
    for (int k = 0; k < 3; ++k) q[k] = l[k] * *inv_w_[k];
    const F sum = q[0] + q[1] + q[2], inv_sum = 1.0f / sum;
    for (F& qk : q) qk *= inv_sum;
    for (int c : {0, 1, 2, 3}) {
      if (c >= colours && c < 3) continue;
      rgba[c] =
          flat_color_ ? F{} + color_[0][c] : q[0] * color_[0][c] + q[1] * color_[1][c] + q[2] * color_[2][c];
    }
    F texel[4];
    if (texture_) {
      sample(*texture_, q, inv_sum, lanes, texel);
      for (int c = 0; c < 4; ++c) rgba[c] *= texel[c];
    }
    if (!normal_at_[0]) return;
    F n[3], p[3] = {}, shade[3];
    for (int c = 0; c < 3; ++c)
      n[c] = q[0] * normal_at_[0][c] + q[1] * normal_at_[1][c] + q[2] * normal_at_[2][c];
    F len = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    sqrt_lanes(len);
    // A degenerate interpolated normal (opposite vertex normals cancelling) gets the ambient light only.
    const F scale = len > 0.0f ? flip_ / len : F{};
    for (F& c : n) c *= scale;
    if (position_at_[0])
      for (int c = 0; c < 3; ++c)
        p[c] = q[0] * position_at_[0][c] + q[1] * position_at_[1][c] + q[2] * position_at_[2][c];
    if (specular_) {  // decided per draw call: a mesh without specular materials never comes here
      F mr[2] = {F{} + specular_->metallic, F{} + specular_->roughness};
      if (metal_rough_) {  // glTF: B is metallic, G roughness (linear values, read as they are stored)
        sample(*metal_rough_, q, inv_sum, lanes, texel);
        mr[0] *= texel[2], mr[1] *= texel[1];
      }
      specular_lanes<colours>(*rig_, *specular_, n, p, mr, rgba);
      return;
    }
    light_lanes<colours>(*rig_, n, p, shade);
    for (int c = 0; c < colours; ++c) rgba[c] *= shade[c];
  }

 private:
  // `chain` at the perspective-correct coordinates into texel (0..1), lane by lane (texels are fetched one
  // pixel at a time; lanes not in `lanes` are 1). The level of detail comes from the screen derivatives of
  // u / w and v / w over 1 / w.
  template <class F>
  [[gnu::always_inline]] inline void sample(const MipChain& chain, const F (&q)[3], const F& inv_sum,
                                            unsigned lanes, F (&texel)[4]) const {
    const F u = q[0] * uv_[0][0] + q[1] * uv_[1][0] + q[2] * uv_[2][0];
    const F v = q[0] * uv_[0][1] + q[1] * uv_[1][1] + q[2] * uv_[2][1];
    const float* d = uv_slopes_;
    const float sx = static_cast<float>(chain.texture->scale[0]),
                sy = static_cast<float>(chain.texture->scale[1]);
    const F du_dx = (d[0] - u * d[2]) * inv_sum * sx, dv_dx = (d[1] - v * d[2]) * inv_sum * sy;
    const F du_dy = (d[3] - u * d[5]) * inv_sum * sx, dv_dy = (d[4] - v * d[5]) * inv_sum * sy;
    for (F& t : texel) t = F{} + 1.0f;
    const MipLevel& base = chain.levels[0];
    for (unsigned m = lanes; m; m &= m - 1) {
      const int i = __builtin_ctz(m);
      const double lod =
          mip_lod(lane(du_dx, i), lane(dv_dx, i), lane(du_dy, i), lane(dv_dy, i), base.width, base.height);
      float t[4];
      detail::sample(chain, lane(u, i), lane(v, i), lod, t);
      for (int c = 0; c < 4; ++c) set_lane(texel[c], i, t[c]);
    }
  }
  static void set_lane(float& v, int, float x) { v = x; }
  static void set_lane(FloatLanes& v, int i, float x) { v[i] = x; }

  const LightRig* rig_ = nullptr;
  float flip_ = 1;  // two-sided lighting: a back face is lit from the side seen
  // Vertex k's values in the record (flat colour: the face's for every k); nullptr where there are none.
  const float* inv_w_[3] = {};
  const float* color_[3] = {};
  bool flat_color_ = true;
  const float* normal_at_[3] = {};         // lit per pixel
  const float* position_at_[3] = {};       // lit per pixel by a point light
  const MipChain* texture_ = nullptr;      // textured faces with a texture
  const Specular* specular_ = nullptr;     // faces of a specular material (else Lambert)
  const MipChain* metal_rough_ = nullptr;  // specular faces with a metallic-roughness texture
  const float* uv_[3] = {};
  float uv_slopes_[6] = {};  // d(u/w)/dx, d(v/w)/dx, d(1/w)/dx, then the same per pixel down
};

}  // namespace raster::detail
