// Texture sampling for shade: the one routine that reads a mip chain (base/mip_chain.h): bilinear within a
// level, linear between levels (trilinear) when the texture is minified, with repeat or clamp addressing.
// Filtering happens in linear light: texels are decoded through srgb.h's table, weighted, and the result
// encoded back.
#pragma once

#include "base/mip_chain.h"
#include "base/srgb.h"

namespace raster::detail {

/// The filtered colour of `chain` at texture coordinate (u, v) (scene.h: v up) and level of detail `lod`
/// (log2 of texels per pixel; <= 0 magnifies): RGB in 0..1, sRGB-encoded, alpha 0..1.
void sample(const MipChain& chain, double u, double v, double lod, float (&out)[4]);

/// The level of detail of a pixel footprint: log2 of the longer of the texel-space vectors (du/dx, dv/dx)
/// and (du/dy, dv/dy) per pixel, scaled by the texture's size. Not finite inputs give 0.
double mip_lod(double du_dx, double dv_dx, double du_dy, double dv_dy, int width, int height);

}  // namespace raster::detail
