#include "shade/texture.h"

#include <algorithm>
#include <cmath>

namespace raster::detail {
namespace {

// Wraps a texel index into [0, size): repeat (mod) or clamp.
int address(double t, int size, bool clamp) {
  if (clamp) return static_cast<int>(std::clamp(t, 0.0, size - 1.0));
  const double m = t - std::floor(t / size) * size;  // in [0, size] (size only by rounding)
  const int i = static_cast<int>(m);
  return i >= size ? 0 : i;
}

// Bilinear in linear light at level `lv`; accumulates weight * premultiplied colour and weight * alpha.
void bilinear(const MipLevel& lv, double u, double v, bool clamp, double weight, double (&acc)[4]) {
  const double x = u * lv.width - 0.5, y = (1 - v) * lv.height - 0.5;  // texel centres at integers
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  const int x0 = address(fx, lv.width, clamp), x1 = address(fx + 1, lv.width, clamp);
  const int y0 = address(fy, lv.height, clamp), y1 = address(fy + 1, lv.height, clamp);
  const int xs[2] = {x0, x1}, ys[2] = {y0, y1};
  const double wx[2] = {1 - tx, tx}, wy[2] = {1 - ty, ty};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const double w = weight * wx[i] * wy[j];
      if (w == 0) continue;
      const std::uint8_t* t = lv.rgba + (std::size_t(ys[j]) * std::size_t(lv.width) + std::size_t(xs[i])) * 4;
      const double a = t[3] / 255.0;
      acc[0] += w * a * srgb_to_linear(t[0]), acc[1] += w * a * srgb_to_linear(t[1]);
      acc[2] += w * a * srgb_to_linear(t[2]), acc[3] += w * a;
    }
}

}  // namespace

double mip_lod(double du_dx, double dv_dx, double du_dy, double dv_dy, int width, int height) {
  const double x = std::hypot(du_dx * width, dv_dx * height), y = std::hypot(du_dy * width, dv_dy * height);
  const double rho = std::max(x, y);
  if (!(rho > 0) || !std::isfinite(rho)) return 0;
  return std::log2(rho);
}

void sample(const MipChain& chain, double u, double v, double lod, float (&out)[4]) {
  const Texture* texture = chain.texture;
  const std::vector<MipLevel>& levels = chain.levels;
  if (!std::isfinite(u) || !std::isfinite(v)) u = v = 0;
  u = u * texture->scale[0] + texture->offset[0];
  v = v * texture->scale[1] + texture->offset[1];
  double acc[4] = {};
  const int last = static_cast<int>(levels.size()) - 1;
  if (!(lod > 0)) {
    bilinear(levels[0], u, v, texture->clamp, 1, acc);
  } else {
    const double level = std::min(lod, static_cast<double>(last));
    const int l0 = static_cast<int>(level);
    const double f = level - l0;
    bilinear(levels[l0], u, v, texture->clamp, 1 - f, acc);
    if (f > 0) bilinear(levels[std::min(l0 + 1, last)], u, v, texture->clamp, f, acc);
  }
  const double a = acc[3];
  for (int c = 0; c < 3; ++c) out[c] = a > 0 ? linear_to_srgb(static_cast<float>(acc[c] / a)) / 255.0f : 0.0f;
  out[3] = static_cast<float>(a);
}

}  // namespace raster::detail
