// Texture reads of the engine, as GL's sampler with ShaderToy's default settings: GL_REPEAT, bilinear
// within a level, linear between levels (GL_LINEAR_MIPMAP_LINEAR), texel bytes as stored / 255 (no sRGB
// decoding). Texture coordinates run from the image's bottom row (v = 0), as ShaderToy uploads images
// flipped. The level of detail comes from the 2x2 quad's coordinate differences, one per quad.
#include <bit>
#include <cmath>
#include <cstring>

#include "shader/engine_lane_ops.h"

namespace raster::shader::run {
namespace {

float as_float(std::uint32_t u) {
  return std::bit_cast<float>(u);
}
std::uint32_t bits(float f) {
  return std::bit_cast<std::uint32_t>(f);
}

int wrap(int i, int n) {
  const int m = i % n;
  return m < 0 ? m + n : m;
}

// Texel (x, y) of a level, y counted from the bottom row, as four floats 0..1.
void texel(const detail::MipLevel& level, int x, int y, float out[4]) {
  const std::uint8_t* p = level.rgba + (static_cast<std::size_t>(level.height - 1 - y) * level.width + x) * 4;
  for (int k = 0; k < 4; ++k) out[k] = static_cast<float>(p[k]) * (1.0f / 255.0f);
}

// Bilinear at (u, v) in level coordinates of 0..1 a side, with a texel offset; repeat.
void bilinear(const detail::MipLevel& level, float u, float v, int ox, int oy, float out[4]) {
  const float x = u * static_cast<float>(level.width) - 0.5f;
  const float y = v * static_cast<float>(level.height) - 0.5f;
  // Coordinates far outside the image: what repeats is the fraction, so only it is kept.
  const float fx = x - std::floor(x), fy = y - std::floor(y);
  const double bx = std::floor(static_cast<double>(x)), by = std::floor(static_cast<double>(y));
  const auto cell = [](double c, int n) { return static_cast<int>(c - std::floor(c / n) * n); };
  const int x0 = wrap(cell(std::isfinite(bx) ? bx : 0.0, level.width) + ox, level.width);
  const int y0 = wrap(cell(std::isfinite(by) ? by : 0.0, level.height) + oy, level.height);
  const int x1 = wrap(x0 + 1, level.width), y1 = wrap(y0 + 1, level.height);
  float t00[4], t10[4], t01[4], t11[4];
  texel(level, x0, y0, t00), texel(level, x1, y0, t10), texel(level, x0, y1, t01), texel(level, x1, y1, t11);
  for (int k = 0; k < 4; ++k) {
    const float bottom = t00[k] + (t10[k] - t00[k]) * fx;
    const float top = t01[k] + (t11[k] - t01[k]) * fx;
    out[k] = bottom + (top - bottom) * fy;
  }
}

// log2 of the larger of the two screen-axis footprints (GL's scale factor), from the quad's top-left
// lane's differences to its right and lower neighbours.
float implicit_lod(const std::uint32_t* u, const std::uint32_t* v, int lane, const detail::MipLevel& base) {
  const int tl = lane & ~9;
  const float w = static_cast<float>(base.width), h = static_cast<float>(base.height);
  const float dudx = (as_float(u[tl | 1]) - as_float(u[tl])) * w,
              dvdx = (as_float(v[tl | 1]) - as_float(v[tl])) * h;
  const float dudy = (as_float(u[tl | 8]) - as_float(u[tl])) * w,
              dvdy = (as_float(v[tl | 8]) - as_float(v[tl])) * h;
  const float rho = std::fmax(std::sqrt(dudx * dudx + dvdx * dvdx), std::sqrt(dudy * dudy + dvdy * dvdy));
  return std::log2(rho);
}

}  // namespace

void sample(const Instr& in, std::uint32_t* r, const RunContext& context) {
  std::uint32_t* d = r + static_cast<std::size_t>(in.d) * kBlockLanes;
  const std::uint32_t* u = r + static_cast<std::size_t>(in.a) * kBlockLanes;
  const std::uint32_t* v = r + static_cast<std::size_t>(in.b) * kBlockLanes;
  const std::uint32_t* c = r + static_cast<std::size_t>(in.c) * kBlockLanes;
  const ChannelImage* image = context.channels[in.imm & 0xff];
  const int ox = static_cast<int>(in.imm >> 8 & 0xff) - 8, oy = static_cast<int>(in.imm >> 16 & 0xff) - 8;
  const auto mode = static_cast<TexMode>(in.flags);
  for (int l = 0; l < kBlockLanes; ++l) {
    float out[4] = {0, 0, 0, 0};
    if (image && !image->levels.empty()) {
      const detail::MipLevel& base = image->levels[0];
      float lod = 0;
      if (mode == TexMode::lod) {
        lod = as_float(c[l]);
      } else if (mode == TexMode::grad) {
        const float w = static_cast<float>(base.width), h = static_cast<float>(base.height);
        const float* g = reinterpret_cast<const float*>(c);
        const float dudx = g[l] * w, dvdx = g[kBlockLanes + l] * h;
        const float dudy = g[2 * kBlockLanes + l] * w, dvdy = g[3 * kBlockLanes + l] * h;
        lod =
            std::log2(std::fmax(std::sqrt(dudx * dudx + dvdx * dvdx), std::sqrt(dudy * dudy + dvdy * dvdy)));
      } else {
        lod = implicit_lod(u, v, l, base) + (mode == TexMode::bias ? as_float(c[l]) : 0.0f);
      }
      const float top = static_cast<float>(image->levels.size() - 1);
      lod = std::isnan(lod) ? 0.0f : lod < 0.0f ? 0.0f : lod > top ? top : lod;
      const int l0 = static_cast<int>(lod);
      const int l1 = l0 + 1 < static_cast<int>(image->levels.size()) ? l0 + 1 : l0;
      const float f = lod - static_cast<float>(l0);
      float a[4], b[4];
      const float su = as_float(u[l]), sv = as_float(v[l]);
      bilinear(image->levels[static_cast<std::size_t>(l0)], std::isfinite(su) ? su : 0.0f,
               std::isfinite(sv) ? sv : 0.0f, ox, oy, a);
      if (f > 0.0f) {
        bilinear(image->levels[static_cast<std::size_t>(l1)], std::isfinite(su) ? su : 0.0f,
                 std::isfinite(sv) ? sv : 0.0f, ox, oy, b);
        for (int k = 0; k < 4; ++k) a[k] = a[k] + (b[k] - a[k]) * f;
      }
      std::memcpy(out, a, sizeof out);
    }
    for (int k = 0; k < 4; ++k) d[k * kBlockLanes + l] = bits(out[k]);
  }
}

// texelFetch: the texel at integer (x, y) of a level, zero outside the level (or past the last one).
void fetch(const Instr& in, std::uint32_t* r, const RunContext& context) {
  std::uint32_t* d = r + static_cast<std::size_t>(in.d) * kBlockLanes;
  const std::uint32_t* xs = r + static_cast<std::size_t>(in.a) * kBlockLanes;
  const std::uint32_t* ys = r + static_cast<std::size_t>(in.b) * kBlockLanes;
  const std::uint32_t* lods = r + static_cast<std::size_t>(in.c) * kBlockLanes;
  const ChannelImage* image = context.channels[in.imm & 0xff];
  for (int l = 0; l < kBlockLanes; ++l) {
    float out[4] = {0, 0, 0, 0};
    const auto x = static_cast<std::int32_t>(xs[l]), y = static_cast<std::int32_t>(ys[l]);
    const auto lod = static_cast<std::int32_t>(lods[l]);
    if (image && lod >= 0 && static_cast<std::size_t>(lod) < image->levels.size()) {
      const detail::MipLevel& level = image->levels[static_cast<std::size_t>(lod)];
      if (x >= 0 && y >= 0 && x < level.width && y < level.height) texel(level, x, y, out);
    }
    for (int k = 0; k < 4; ++k) d[k * kBlockLanes + l] = bits(out[k]);
  }
}

// textureSize: a level's size, zero past the last level.
void texture_size(const Instr& in, std::uint32_t* r, const RunContext& context) {
  std::uint32_t* d = r + static_cast<std::size_t>(in.d) * kBlockLanes;
  const std::uint32_t* lods = r + static_cast<std::size_t>(in.a) * kBlockLanes;
  const ChannelImage* image = context.channels[in.imm & 0xff];
  for (int l = 0; l < kBlockLanes; ++l) {
    const auto lod = static_cast<std::int32_t>(lods[l]);
    const bool ok = image && lod >= 0 && static_cast<std::size_t>(lod) < image->levels.size();
    d[l] = ok ? static_cast<std::uint32_t>(image->levels[static_cast<std::size_t>(lod)].width) : 0;
    d[kBlockLanes + l] =
        ok ? static_cast<std::uint32_t>(image->levels[static_cast<std::size_t>(lod)].height) : 0;
  }
}

}  // namespace raster::shader::run
