// Texture sampling for shade: a decoded Texture (scene.h) -> its mip chain, made once per render, and the
// one routine that reads it: bilinear within a level, linear between levels (trilinear) when the texture
// is minified, with repeat or clamp addressing. Filtering happens in linear light: texels are sRGB-encoded
// and are decoded through a table, weighted, and the result encoded back (an average of sRGB bytes is too
// dark: a black/white checker seen from afar must be 50% light, byte 188, not 128).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/stop.h"
#include "raster/scene.h"

namespace raster::detail {

/// One level of a mip chain: `width` x `height` texels of straight RGBA8, sRGB colour, rows from the top.
struct MipLevel {
  int width = 0, height = 0;
  const std::uint8_t* rgba = nullptr;
};

/// A texture and its mipmaps: level 0 is the texture's own texels (not copied), level k + 1 halves each
/// side of level k (floor, at least 1), filtered 2x2 in linear light weighted by alpha.
struct MipChain {
  const Texture* texture = nullptr;
  std::vector<MipLevel> levels;
  std::vector<std::unique_ptr<std::uint8_t[]>> storage;  ///< levels 1.. (level 0 lives in the Texture)

  /// The filtered colour at texture coordinate (u, v) (scene.h: v up) and level of detail `lod` (log2 of
  /// texels per pixel; <= 0 magnifies): RGB in 0..1, sRGB-encoded, alpha 0..1.
  void sample(double u, double v, double lod, float (&out)[4]) const;
};

/// Builds the chain (levels 1.. allocated here; their bytes are mip_bytes()). With a meter, the work is
/// counted a texel at a time and building stops, leaving a partial chain, once the meter says the render
/// must stop; the caller looks at meter->stopped().
MipChain build_mips(const Texture& texture, StopMeter* meter = nullptr);

/// Bytes the mip levels above level 0 of a w x h texture take.
std::int64_t mip_bytes(int width, int height);

/// The level of detail of a pixel footprint: log2 of the longer of the texel-space vectors (du/dx, dv/dx)
/// and (du/dy, dv/dy) per pixel, scaled by the texture's size. Not finite inputs give 0.
double mip_lod(double du_dx, double dv_dx, double du_dy, double dv_dy, int width, int height);

/// sRGB byte -> linear light in 0..1, and back (rounded to nearest), both exact tables of the sRGB curve.
float srgb_to_linear(std::uint8_t v);
std::uint8_t linear_to_srgb(float v);

}  // namespace raster::detail
