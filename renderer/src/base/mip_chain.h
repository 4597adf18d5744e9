// Mip chains: a decoded Texture (scene.h) and its halved levels, made once per render by geometry (which
// keeps them in the Setup, setup.h), sized by the plan (mip_bytes, asked of the memory budget) and read by
// shade's sampler (shade/texture.h). Levels are filtered in linear light: texels are sRGB-encoded, decoded
// through srgb.h's table, weighted and encoded back (an average of sRGB bytes is too dark: a black/white
// checker seen from afar must be 50% light, byte 188, not 128).
#pragma once

#include <cstdint>
#include <memory>
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
};

/// Builds the chain (levels 1.. allocated here; their bytes are mip_bytes()). With a meter, the work is
/// counted a texel at a time and building stops, leaving a partial chain, once the meter says the render
/// must stop; the caller looks at meter->stopped().
MipChain build_mips(const Texture& texture, StopMeter* meter = nullptr);

/// The same with the bytes averaged as stored, not in linear light (GL's glGenerateMipmap for RGBA8): the
/// chain a shader's channel samples.
MipChain build_raw_mips(const Texture& texture, StopMeter* meter = nullptr);

/// Bytes the mip levels above level 0 of a w x h texture take.
std::int64_t mip_bytes(int width, int height);

}  // namespace raster::detail
