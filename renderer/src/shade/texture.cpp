#include "shade/texture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

namespace raster::detail {
namespace {

double srgb_decode(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

struct Tables {
  std::array<float, 256> to_linear;
  // linear -> byte: the byte whose interval [decode(b - 1/2), decode(b + 1/2)) holds the value, i.e. the
  // number of the 255 thresholds between neighbouring bytes that are <= the value (exact rounding in the
  // encoded domain). Found in O(1): the thresholds are at least decode(1.5/255) - decode(0.5/255) = 3.0e-4
  // apart, wider than a bucket of 1/kBuckets = 2.4e-4, so a bucket holds at most one threshold, and the
  // byte is the count below the bucket's start plus one comparison.
  static constexpr int kBuckets = 4096;
  std::array<float, 256> threshold;  // 255 used; [255] = +inf so the comparison never runs past the end
  std::array<std::uint8_t, kBuckets + 1> below;  // thresholds < bucket k's start k / kBuckets
  Tables() {
    for (int i = 0; i < 256; ++i) to_linear[i] = static_cast<float>(srgb_decode(i / 255.0));
    for (int i = 0; i < 255; ++i) threshold[i] = static_cast<float>(srgb_decode((i + 0.5) / 255.0));
    threshold[255] = std::numeric_limits<float>::infinity();
    for (int k = 0, b = 0; k <= kBuckets; ++k) {
      while (b < 255 && threshold[b] < static_cast<float>(k) / kBuckets) ++b;
      below[k] = static_cast<std::uint8_t>(b);
    }
  }
};
const Tables kTables;

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
      acc[0] += w * a * kTables.to_linear[t[0]], acc[1] += w * a * kTables.to_linear[t[1]];
      acc[2] += w * a * kTables.to_linear[t[2]], acc[3] += w * a;
    }
}

}  // namespace

float srgb_to_linear(std::uint8_t v) {
  return kTables.to_linear[v];
}

std::uint8_t linear_to_srgb(float v) {
  if (!(v > 0)) return 0;  // and NaN
  if (v >= 1) return 255;
  int b = kTables.below[static_cast<int>(v * Tables::kBuckets)];
  b += v >= kTables.threshold[b];  // the one threshold this bucket may hold
  return static_cast<std::uint8_t>(b);
}

std::int64_t mip_bytes(int width, int height) {
  std::int64_t bytes = 0;
  while (width > 1 || height > 1) {
    width = std::max(1, width / 2), height = std::max(1, height / 2);
    bytes += std::int64_t{width} * height * 4;
  }
  return bytes;
}

MipChain build_mips(const Texture& texture, StopMeter* meter) {
  MipChain chain;
  chain.texture = &texture;
  chain.levels.push_back({texture.width, texture.height, texture.rgba.data()});
  while (chain.levels.back().width > 1 || chain.levels.back().height > 1) {
    const MipLevel from = chain.levels.back();
    const int w = std::max(1, from.width / 2), h = std::max(1, from.height / 2);
    // Not zeroed: every byte is written below (a 4096^2 chain is 21 MB).
    std::uint8_t* const out =
        chain.storage
            .emplace_back(std::make_unique_for_overwrite<std::uint8_t[]>(std::size_t(w) * std::size_t(h) * 4))
            .get();
    // Texel 2x + 1 (row 2y + 1) exists unless that side of `from` is 1 (an odd side's last one is dropped).
    const std::size_t dx = from.width > 1 ? 4 : 0, dy = from.height > 1 ? std::size_t(from.width) * 4 : 0;
    for (int y = 0; y < h; ++y) {
      // A 4096^2 texture's chain is 5.6M texels: the render's deadline is asked as for a row of pixels.
      if (meter && meter->add(w)) return chain;
      const std::uint8_t* row = from.rgba + std::size_t(2 * y) * std::size_t(from.width) * 4;
      std::uint8_t* o = out + std::size_t(y) * std::size_t(w) * 4;
      for (int x = 0; x < w; ++x, o += 4) {
        const std::uint8_t* q = row + std::size_t(8 * x);
        const std::uint8_t* taps[4] = {q, q + dx, q + dy, q + dy + dx};
        float acc[4] = {};  // premultiplied linear colour, alpha (0..255)
        if ((taps[0][3] & taps[1][3] & taps[2][3] & taps[3][3]) == 255) {  // opaque: a plain average
          for (const std::uint8_t* t : taps)
            for (int c = 0; c < 3; ++c) acc[c] += kTables.to_linear[t[c]];
          for (int c = 0; c < 3; ++c) o[c] = linear_to_srgb(acc[c] * 0.25f);
          o[3] = 255;
          continue;
        }
        for (const std::uint8_t* t : taps) {
          const float a = t[3];
          for (int c = 0; c < 3; ++c) acc[c] += a * kTables.to_linear[t[c]];
          acc[3] += a;
        }
        for (int c = 0; c < 3; ++c) o[c] = acc[3] > 0 ? linear_to_srgb(acc[c] / acc[3]) : 0;
        o[3] = static_cast<std::uint8_t>(std::lround(acc[3] * 0.25f));
      }
    }
    chain.levels.push_back({w, h, out});
  }
  return chain;
}

double mip_lod(double du_dx, double dv_dx, double du_dy, double dv_dy, int width, int height) {
  const double x = std::hypot(du_dx * width, dv_dx * height), y = std::hypot(du_dy * width, dv_dy * height);
  const double rho = std::max(x, y);
  if (!(rho > 0) || !std::isfinite(rho)) return 0;
  return std::log2(rho);
}

void MipChain::sample(double u, double v, double lod, float (&out)[4]) const {
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
