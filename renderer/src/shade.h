// Shade: covered blocks (coverage.h) + a record's attributes -> pixels. The only place a colour is
// computed: interpolation of the attribute planes, perspective correction, Lambert lighting (per face, for
// geometry to bake in, and per pixel), clamping, and how it is written (store or source-over blend).
// Templated on the framebuffer's channel count so the per-pixel code has no format branches.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <bit>
#include <cstring>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "coverage.h"
#include "raster/image.h"
#include "raster/scene.h"
#include "setup.h"

namespace raster::detail {

/// A channel value (0..255 scale) rounded to a byte; out-of-range values clamp and NaN becomes 0, so a
/// float never reaches an integer conversion it cannot survive.
inline std::uint8_t to_byte(double x) {
  if (!(x > 0)) return 0;  // also NaN
  return x >= 254.5 ? 255 : static_cast<std::uint8_t>(x + 0.5);
}

/// round(x / 255) for 0 <= x <= 255 * 255 * 2, exact.
inline std::uint32_t div255(std::uint32_t x) {
  return (x + 127) / 255;
}

/// Writes an opaque-or-replacing colour. Grey formats use r (the plan chose grey only if r == g == b).
template <int C>
inline void store(std::uint8_t* px, Rgba8 c) {
  if constexpr (C == 1) {
    px[0] = c.r;
  } else if constexpr (C == 2) {
    px[0] = c.r, px[1] = c.a;
  } else if constexpr (C == 3) {
    px[0] = c.r, px[1] = c.g, px[2] = c.b;
  } else {
    px[0] = c.r, px[1] = c.g, px[2] = c.b, px[3] = c.a;
  }
}

/// Source-over with straight alpha. Formats without alpha hold an opaque destination, which keeps the
/// simple form; formats with alpha use the general one.
template <int C>
inline void blend(std::uint8_t* px, Rgba8 c) {
  const std::uint32_t sa = c.a, ia = 255 - sa;
  if constexpr (C == 1 || C == 3) {
    px[0] = static_cast<std::uint8_t>(div255(c.r * sa + px[0] * ia));
    if constexpr (C == 3) {
      px[1] = static_cast<std::uint8_t>(div255(c.g * sa + px[1] * ia));
      px[2] = static_cast<std::uint8_t>(div255(c.b * sa + px[2] * ia));
    }
  } else {
    constexpr int alpha_index = C - 1;
    const std::uint32_t da = px[alpha_index];
    // Output alpha and colours scaled by 255 * 255 to stay in integers: oa = sa + da (1 - sa).
    const std::uint32_t oa = sa * 255 + da * ia;
    if (oa == 0) {
      store<C>(px, Rgba8{0, 0, 0, 0});
      return;
    }
    auto mix = [&](std::uint32_t s, std::uint32_t d) {
      return static_cast<std::uint8_t>((s * sa * 255 + d * da * ia + oa / 2) / oa);
    };
    px[0] = mix(c.r, px[0]);
    if constexpr (C == 4) {
      px[1] = mix(c.g, px[1]);
      px[2] = mix(c.b, px[2]);
    }
    px[alpha_index] = static_cast<std::uint8_t>(div255(oa));
  }
}

/// Source-over of `c` at opacity `w` in [0, 1] (a covered share times the colour's own alpha / 255), rounded
/// to nearest: how area coverage composites a cut pixel.
template <int C>
inline void blend_weighted(std::uint8_t* px, Rgba8 c, float w) {
  if constexpr (C == 1 || C == 3) {
    // d + (s - d) w lies between s and d, so adding 0.5 and truncating rounds without leaving 0..255.
    auto mix = [&](std::uint8_t s, std::uint8_t d) {
      return static_cast<std::uint8_t>(static_cast<float>(d) + static_cast<float>(s - d) * w + 0.5f);
    };
    px[0] = mix(c.r, px[0]);
    if constexpr (C == 3) px[1] = mix(c.g, px[1]), px[2] = mix(c.b, px[2]);
  } else {
    constexpr int alpha_index = C - 1;
    const float da = px[alpha_index] / 255.0f, keep = da * (1 - w), oa = w + keep;
    if (!(oa > 0)) {
      store<C>(px, Rgba8{0, 0, 0, 0});
      return;
    }
    auto mix = [&](std::uint8_t s, std::uint8_t d) {
      return static_cast<std::uint8_t>((static_cast<float>(s) * w + static_cast<float>(d) * keep) / oa + 0.5f);
    };
    px[0] = mix(c.r, px[0]);
    if constexpr (C == 4) px[1] = mix(c.g, px[1]), px[2] = mix(c.b, px[2]);
    px[alpha_index] = static_cast<std::uint8_t>(oa * 255 + 0.5f);
  }
}

/// Floats a pixel of a union-coverage tile holds (Surface::coverage): the summed share, then the sums of
/// share x R, G, B, A (0..255 scale).
inline constexpr int kUnionFloats = 5;

/// Composites the primitive accumulated in `surface.coverage` over `rect`: each pixel with a share takes the
/// share-weighted mean colour at opacity min(1, summed share) x alpha; the accumulation is cleared for the
/// next primitive.
template <int C>
void composite_union(const Surface& surface, Rect rect) {
  // Only the pixels accumulated into (Surface::expanded's bits): a thin diagonal line reaches few of its
  // box's pixels.
  for (int y0 = rect.y0 - (rect.y0 - surface.y0) % 8; y0 < rect.y1; y0 += 8)
    for (int x0 = rect.x0 - (rect.x0 - surface.x0) % 8; x0 < rect.x1; x0 += 8) {
      std::uint64_t& touched = surface.expanded_bits(x0, y0);
      for (std::uint64_t m = touched; m; m &= m - 1) {
        const int bit = std::countr_zero(m), x = x0 + (bit & 7), y = y0 + (bit >> 3);
        float* acc = surface.coverage + surface.index(x, y) * kUnionFloats;
        const float share = acc[0];
        auto channel = [&](int k) { return static_cast<std::uint8_t>(std::min(255.0f, acc[1 + k] / share + 0.5f)); };
        const Rgba8 c{channel(0), channel(1), channel(2), channel(3)};
        blend_weighted<C>(surface.pixel(x, y), c, std::min(share, 1.0f) * (c.a / 255.0f));
        std::fill_n(acc, kUnionFloats, 0.0f);
      }
      touched = 0;
    }
}

/// Multisampling: each pixel of `rect` whose samples differ becomes their mean, rounded to nearest (for
/// formats with alpha, the mean of premultiplied values: a transparent sample adds no colour); the others
/// already hold their one colour.
template <int C>
void resolve_samples(const Surface& surface, Rect rect) {
  const int n = surface.sample_count;
  for (int y0 = rect.y0; y0 < rect.y1; y0 += 8)
    for (int x0 = rect.x0; x0 < rect.x1; x0 += 8) {
      std::uint64_t& bits = surface.expanded_bits(x0, y0);
      for (std::uint64_t m = bits; m; m &= m - 1) {
        const int bit = std::countr_zero(m);
        const std::size_t index = surface.index(x0 + (bit & 7), y0 + (bit >> 3));
        auto sample = [&](int s) { return surface.samples + (static_cast<std::size_t>(s) * surface.plane + index) * C; };
        std::uint8_t* out = surface.color + index * C;
        if constexpr (C == 1 || C == 3) {
          for (int k = 0; k < C; ++k) {
            std::uint32_t sum = 0;
            for (int s = 0; s < n; ++s) sum += sample(s)[k];
            out[k] = static_cast<std::uint8_t>((sum + n / 2) / n);
          }
        } else {
          std::uint32_t alpha = 0;
          for (int s = 0; s < n; ++s) alpha += sample(s)[C - 1];
          for (int k = 0; k + 1 < C; ++k) {
            std::uint32_t weighted = 0;
            for (int s = 0; s < n; ++s) weighted += std::uint32_t{sample(s)[k]} * sample(s)[C - 1];
            out[k] = alpha ? static_cast<std::uint8_t>((weighted + alpha / 2) / alpha) : 0;
          }
          out[C - 1] = static_cast<std::uint8_t>((alpha + n / 2) / n);
        }
      }
      bits = 0;
    }
}

/// floor(x) for |x| < 2^62, without a library call.
inline std::int64_t floor_to_int(double x) {
  const auto i = static_cast<std::int64_t>(x);  // toward zero
  return i - (x < static_cast<double>(i));
}

/// For each 8-bit row mask, the bytes of an 8-pixel row of C channels that belong to covered pixels (0xff),
/// padded to 32 bytes.
template <int C>
struct ByteMasks {
  alignas(16) std::uint8_t mask[256][32];
  constexpr ByteMasks() : mask{} {
    for (int bits = 0; bits < 256; ++bits)
      for (int i = 0; i < 8; ++i)
        for (int c = 0; c < C; ++c) mask[bits][i * C + c] = (bits >> i) & 1 ? 0xff : 0;
  }
  const std::uint8_t* operator[](unsigned bits) const { return mask[bits]; }
};
template <int C>
inline constexpr ByteMasks<C> kByteMasks{};

/// Lambert under the view's lights (scene.h: Light): `out` = the sum over lights of colour x intensity x
/// (ambient: 1; directional, point: max(0, n . toward the light)), for the unit normal n of the side seen at
/// world point p. Used per face by geometry (flat lighting) and per pixel below.
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

/// Shades the blocks of one triangle record inside one tile. Made per record per tile: everything that
/// depends only on the record is worked out here, once, not per block.
template <int C>
class TriangleShader {
 public:
  /// `step_x` and `step_y` are the record's edge-value steps per pixel right and down (256 a_k, 256 b_k) and
  /// `area` its doubled area, as doubles (exact for the fast range).
  TriangleShader(const DrawCall& call, const TriangleRecord& record, const float* attributes,
                 const Surface& surface, const double (&step_x)[3], const double (&step_y)[3], double area)
      : call_(call), mode_(call.mode), attr_(attributes), surface_(surface),
        flip_(record.back_facing ? -1.0 : 1.0), union_(call.mode.union_coverage && surface.coverage),
        msaa_(surface.sample_count > 1) {
    const AttributeLayout& layout = call.layout;
    depth_at_ = layout.depth >= 0 ? attr_ + layout.depth : nullptr;
    inv_w_at_ = layout.inv_w >= 0 ? attr_ + layout.inv_w : nullptr;
    normal_at_ = layout.normal >= 0 ? attr_ + layout.normal : nullptr;
    position_at_ = layout.position >= 0 ? attr_ + layout.position : nullptr;
    if (layout.uv >= 0 && call.texture) {
      uv_at_ = attr_ + layout.uv;
      for (int k = 0; k < 3; ++k) dl_dx_[k] = step_x[k] / area, dl_dy_[k] = step_y[k] / area;
    }
    flat_ = {to_byte(attr_[0]), to_byte(attr_[1]), to_byte(attr_[2]), to_byte(attr_[3])};
    kind_ = depth_at_ ? Kind::depth : mode_.varying_color ? Kind::smooth : Kind::flat;
    if (msaa_ && depth_at_) {
      // Depth is affine in screen space: each sample's z is the centre's plus a constant per sample.
      double dz_dx = 0, dz_dy = 0;
      for (int k = 0; k < 3; ++k) dz_dx += step_x[k] * depth_at_[k] / area, dz_dy += step_y[k] * depth_at_[k] / area;
      for (int s = 0; s < surface.sample_count; ++s)
        z_offset_[s] = static_cast<float>(dz_dx * (surface.pattern[s].x - 128) / 256.0 +
                                          dz_dy * (surface.pattern[s].y - 128) / 256.0);
    }
    if (kind_ == Kind::flat) {
      for (int i = 0; i < kBlock; ++i) store<C>(row_bytes_ + i * C, flat_);
#if defined(__SSE2__)
      pattern_[0] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row_bytes_));
      pattern_[1] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row_bytes_ + 16));
#endif
    }
    if (kind_ != Kind::smooth) return;
    for (int ch = 0; ch < 4; ++ch) {
      lo_[ch] = std::min({attr_[ch], attr_[4 + ch], attr_[8 + ch]});
      hi_[ch] = std::max({attr_[ch], attr_[4 + ch], attr_[8 + ch]});
    }
    // 16.16 change per pixel right and down, from the exact edge steps; steep ones take the exact path.
    const double scale = 65536.0 / area;
    for (int ch = 0; ch < 4; ++ch) {
      const double v[3] = {attr_[ch], attr_[4 + ch], attr_[8 + ch]};
      const double sx = (step_x[0] * v[0] + step_x[1] * v[1] + step_x[2] * v[2]) * scale;
      const double sy = (step_y[0] * v[0] + step_y[1] * v[1] + step_y[2] * v[2]) * scale;
      steep_ = steep_ || !(std::fabs(sx) < 0x1p40 && std::fabs(sy) < 0x1p40);
      slope_x_[ch] = steep_ ? 0 : floor_to_int(sx + 0.5);
      slope_y_[ch] = steep_ ? 0 : floor_to_int(sy + 0.5);
    }
  }

  /// Every pixel of `clip` is covered; `first` is the block at the clip's block-grid origin (its mask is
  /// all ones, its values exact). Flat opaque colour fills the rows as long runs; anything else is shaded
  /// block by block with exactly the values the blocks would have had.
  void rect(Rect clip, const Block& first) {
    if (kind_ == Kind::flat && !mode_.blend && !union_) {
      for (int y = clip.y0; y < clip.y1; ++y) fill_run(pixel(clip.x0, y), clip.x1 - clip.x0);
      if (msaa_) {  // every sample of these pixels now holds the colour: one value each again
        for (int y0 = first.y0; y0 < clip.y1; y0 += kBlock)
          for (int x0 = first.x0; x0 < clip.x1; x0 += kBlock)
            surface_.expanded_bits(x0, y0) &=
                ~(coverage_detail::row_mask(std::max(0, clip.y0 - y0), std::min(kBlock, clip.y1 - y0)) &
                  coverage_detail::column_mask(std::max(0, clip.x0 - x0), std::min(kBlock, clip.x1 - x0)));
        *surface_.shaded += std::int64_t{clip.x1 - clip.x0} * (clip.y1 - clip.y0);
      }
      return;
    }
    Block b = first;
    for (int y0 = first.y0; y0 < clip.y1; y0 += kBlock) {
      const int r0 = std::max(0, clip.y0 - y0), r1 = std::min(kBlock, clip.y1 - y0);
      const std::uint64_t rows = coverage_detail::row_mask(r0, r1);
      for (int x0 = first.x0; x0 < clip.x1; x0 += kBlock) {
        b.x0 = x0, b.y0 = y0;
        b.mask = rows & coverage_detail::column_mask(std::max(0, clip.x0 - x0), std::min(kBlock, clip.x1 - x0));
        const double bx = (x0 - first.x0) / kBlock, by = (y0 - first.y0) / kBlock;  // exact steps
        for (int k = 0; k < 3; ++k) b.e[k] = first.e[k] + bx * (kBlock * first.dx[k]) + by * (kBlock * first.dy[k]);
        (*this)(b);
      }
    }
  }

  void operator()(const Block& b) {
    if (union_) return accumulate(b, nullptr);
    if (msaa_) return whole(b);
    shade_aliased(b);
  }

  /// Multisampling: `masks[s]` are the pixels whose sample s is covered, `b.mask` their union. Each pixel
  /// is shaded once (at its centre, or at the centroid of its covered samples when the centre is outside)
  /// and the colour goes to the covered samples; whole pixels take the aliased path.
  void samples(const Block& b, const std::uint64_t* masks) {
    const int n = surface_.sample_count;
    if (kind_ == Kind::depth) return depth_samples(b, masks);
    std::uint64_t all = b.mask;
    for (int s = 0; s < n; ++s) all &= masks[s];
    if (all) {
      Block w = b;
      w.mask = all;
      whole(w);
    }
    std::uint64_t& expanded = surface_.expanded_bits(b.x0, b.y0);
    for (std::uint64_t m = b.mask & ~all; m; m &= m - 1) {
      const int bit = std::countr_zero(m), i = bit & 7, r = bit >> 3;
      unsigned covered = 0;
      for (int s = 0; s < n; ++s) covered |= static_cast<unsigned>((masks[s] >> bit) & 1) << s;
      const Rgba8 c = color_at(b, i, r, covered);
      const std::size_t index = surface_.index(b.x0 + i, b.y0 + r);
      if (!((expanded >> bit) & 1)) expand(index), expanded |= std::uint64_t{1} << bit;
      for (unsigned k = covered; k; k &= k - 1) write(sample_pixel(std::countr_zero(k), index), c);
    }
    *surface_.shaded += std::popcount(b.mask & ~all);
  }

  void shade_aliased(const Block& b) {
    switch (kind_) {
      case Kind::flat:
        return shade_flat(b);
      case Kind::smooth:
        return shade_smooth(b);
      case Kind::depth:
        return shade_depth(b);
    }
  }

  /// Area coverage: the pixels of `b.mask` are cut by an edge; each takes its colour at the pixel centre
  /// at opacity share x alpha (or, for a union, adds its share to the primitive's accumulation).
  void area(const Block& b, const AreaCover& cut) {
    if (union_) return accumulate(b, cut.share);
    for (std::uint64_t m = b.mask; m; m &= m - 1) {
      const int bit = std::countr_zero(m), i = bit & 7, r = bit >> 3;
      const Rgba8 c = color_at(b, i, r);
      blend_weighted<C>(pixel(b.x0 + i, b.y0 + r), c, cut.share[bit] * (c.a / 255.0f));
    }
  }

 private:
  std::uint8_t* pixel(int x, int y) const { return surface_.color + surface_.index(x, y) * C; }
  std::uint8_t* sample_pixel(int s, std::size_t index) const {
    return surface_.samples + (static_cast<std::size_t>(s) * surface_.plane + index) * C;
  }

  // A pixel about to get different colours in different samples: each sample starts as its one colour.
  void expand(std::size_t index) const {
    const std::uint8_t* from = surface_.color + index * C;
    for (int s = 0; s < surface_.sample_count; ++s) std::memcpy(sample_pixel(s, index), from, C);
  }

  // Multisampling, pixels with every sample covered (2D). Opaque stores make a pixel's samples one colour
  // again; blending keeps them apart, each sample blended.
  void whole(const Block& b) {
    if (kind_ == Kind::depth) {
      std::uint64_t masks[16];
      std::fill_n(masks, surface_.sample_count, b.mask);
      return depth_samples(b, masks);
    }
    std::uint64_t& expanded = surface_.expanded_bits(b.x0, b.y0);
    *surface_.shaded += std::popcount(b.mask);
    if (!mode_.blend) {
      expanded &= ~b.mask;
      return shade_aliased(b);
    }
    const std::uint64_t mixed = b.mask & expanded;
    if (mixed != b.mask) {
      Block u = b;
      u.mask = b.mask & ~mixed;
      shade_aliased(u);
    }
    const unsigned all = (1u << surface_.sample_count) - 1;
    for (std::uint64_t m = mixed; m; m &= m - 1) {
      const int bit = std::countr_zero(m), i = bit & 7, r = bit >> 3;
      const Rgba8 c = color_at(b, i, r, all);
      const std::size_t index = surface_.index(b.x0 + i, b.y0 + r);
      for (int s = 0; s < surface_.sample_count; ++s) blend<C>(sample_pixel(s, index), c);
    }
  }

  // 3D multisampling: depth tested per sample (the plane at each position), shaded once per pixel.
  void depth_samples(const Block& b, const std::uint64_t* masks) {
    const int n = surface_.sample_count;
    const unsigned all = (1u << n) - 1;
    const double inv_area = 1.0 / b.area;
    const float* z = depth_at_;
    std::uint64_t& expanded = surface_.expanded_bits(b.x0, b.y0);
    for (std::uint64_t m = b.mask; m; m &= m - 1) {
      const int bit = std::countr_zero(m), i = bit & 7, r = bit >> 3;
      const std::size_t index = surface_.index(b.x0 + i, b.y0 + r);
      double l[3];
      for (int k = 0; k < 3; ++k) l[k] = (b.e[k] + i * b.dx[k] + r * b.dy[k]) * inv_area;
      const float centre = static_cast<float>(l[0] * z[0] + l[1] * z[1] + l[2] * z[2]);
      unsigned pass = 0;
      for (int s = 0; s < n; ++s) {
        if (!((masks[s] >> bit) & 1)) continue;
        const float depth = centre + z_offset_[s];
        float& stored = surface_.depth[static_cast<std::size_t>(s) * surface_.plane + index];
        if (depth > stored) stored = depth, pass |= 1u << s;
      }
      if (!pass) continue;
      ++*surface_.shaded;
      unsigned covered = 0;
      for (int s = 0; s < n; ++s) covered |= static_cast<unsigned>((masks[s] >> bit) & 1) << s;
      shading_point(b, i, r, covered, l);
      const Rgba8 c = mode_.smooth ? smooth_color(l) : flat_;
      if (pass == all && !mode_.blend) {
        store<C>(surface_.color + index * C, c);
        expanded &= ~(std::uint64_t{1} << bit);
        continue;
      }
      if (!((expanded >> bit) & 1)) {
        if (pass == all) {  // blending over a pixel whose samples agree: still one colour
          blend<C>(surface_.color + index * C, c);
          continue;
        }
        expand(index), expanded |= std::uint64_t{1} << bit;
      }
      for (unsigned k = pass; k; k &= k - 1) write(sample_pixel(std::countr_zero(k), index), c);
    }
  }

  // Barycentric weights where a pixel is shaded: its centre when the triangle covers the centre (or every
  // sample), else the centroid of its covered samples. `l` holds the centre's on entry.
  void shading_point(const Block& b, int i, int r, unsigned covered, double (&l)[3]) const {
    const unsigned all = (1u << surface_.sample_count) - 1;
    if (covered == all || (!(b.e[0] + i * b.dx[0] + r * b.dy[0] < 0) && !(b.e[1] + i * b.dx[1] + r * b.dy[1] < 0) &&
                           !(b.e[2] + i * b.dx[2] + r * b.dy[2] < 0)))
      return;
    double cx = 0, cy = 0;
    for (unsigned k = covered; k; k &= k - 1) {
      const SamplePoint p = surface_.pattern[std::countr_zero(k)];
      cx += p.x - 128, cy += p.y - 128;
    }
    const double count = std::popcount(covered) * 256.0;
    cx /= count, cy /= count;  // pixels from the centre
    for (int k = 0; k < 3; ++k) l[k] += (cx * b.dx[k] + cy * b.dy[k]) / b.area;
  }

  // The colour at a pixel's centre, from the exact edge values; smooth colours clamp to the vertices' range
  // (a cut pixel's centre may lie outside the triangle).
  // Multisampled, the shading point of a pixel whose samples `covered` are covered (see shading_point).
  Rgba8 color_at(const Block& b, int i, int r, unsigned covered = 0) const {
    if (kind_ != Kind::smooth) return flat_;
    double l[3];
    for (int k = 0; k < 3; ++k) l[k] = (b.e[k] + i * b.dx[k] + r * b.dy[k]) / b.area;
    if (covered) shading_point(b, i, r, covered, l);
    std::uint8_t out[4];
    for (int ch = 0; ch < 4; ++ch) {
      const double v = l[0] * attr_[ch] + l[1] * attr_[4 + ch] + l[2] * attr_[8 + ch];
      out[ch] = to_byte(std::clamp(v, lo_[ch], hi_[ch]));
    }
    return {out[0], out[1], out[2], out[3]};
  }

  // Union coverage: adds share (1 for whole pixels, `shares` for cut ones) and share x colour per pixel.
  void accumulate(const Block& b, const float* shares) const {
    surface_.expanded_bits(b.x0, b.y0) |= b.mask;
    for (std::uint64_t m = b.mask; m; m &= m - 1) {
      const int bit = std::countr_zero(m), i = bit & 7, r = bit >> 3;
      const Rgba8 c = color_at(b, i, r);
      const float share = shares ? shares[bit] : 1.0f;
      float* acc = surface_.coverage + surface_.index(b.x0 + i, b.y0 + r) * kUnionFloats;
      acc[0] += share, acc[1] += share * c.r, acc[2] += share * c.g, acc[3] += share * c.b, acc[4] += share * c.a;
    }
  }

  void write(std::uint8_t* p, Rgba8 c) const {
    if (mode_.blend)
      blend<C>(p, c);
    else
      store<C>(p, c);
  }

  // One colour: a whole row of a block is one copy of eight pixels' bytes.
  void shade_flat(const Block& b) const {
    const std::uint8_t* row_bytes = row_bytes_;
    const Rgba8 flat = flat_;  // locals: pixel stores (through uint8_t*) could alias the members
#if defined(__SSE2__)
    const __m128i pattern[2] = {pattern_[0], pattern_[1]};
#else
    const int pattern[2] = {};
#endif
    for (int r = 0; r < kBlock; ++r) {
      unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (!bits) continue;
      std::uint8_t* row = pixel(b.x0, b.y0 + r);
      if (!mode_.blend) {
#if defined(__SSE2__)
        if constexpr (C == 3 || C == 4) {
          // Whole block rows, the covered bytes chosen by a mask: no branch per row shape to mispredict.
          // The tile storage is whole blocks wide, so the row's other bytes are this tile's own.
          const __m128i* m = reinterpret_cast<const __m128i*>(kByteMasks<C>[bits]);
          __m128i* out = reinterpret_cast<__m128i*>(row);
          const __m128i lo = _mm_loadu_si128(out), lo_m = _mm_load_si128(m);
          _mm_storeu_si128(out, _mm_or_si128(_mm_and_si128(pattern[0], lo_m), _mm_andnot_si128(lo_m, lo)));
          if constexpr (C == 4) {
            const __m128i hi = _mm_loadu_si128(out + 1), hi_m = _mm_load_si128(m + 1);
            _mm_storeu_si128(out + 1, _mm_or_si128(_mm_and_si128(pattern[1], hi_m), _mm_andnot_si128(hi_m, hi)));
          } else {
            const __m128i hi = _mm_loadl_epi64(out + 1), hi_m = _mm_load_si128(m + 1);
            _mm_storel_epi64(out + 1, _mm_or_si128(_mm_and_si128(pattern[1], hi_m), _mm_andnot_si128(hi_m, hi)));
          }
          continue;
        }
#endif
        if (bits == 0xff) {
          store_row_pattern(row, pattern);
          continue;
        }
        const int first = std::countr_zero(bits), last = 31 - std::countl_zero(bits);
        if ((bits >> first) + 1 == 1u << (last - first + 1)) {  // one run: a prefix of the row's bytes
          copy_run(row + first * C, row_bytes, (last - first + 1) * C);
          continue;
        }
      }
      for (; bits; bits &= bits - 1) write(row + std::countr_zero(bits) * C, flat);
    }
  }

  // `n` pixels of the flat colour from `p` on: whole block rows from registers, the rest as a run.
  void fill_run(std::uint8_t* p, int n) const {
#if defined(__SSE2__)
    const __m128i pattern[2] = {pattern_[0], pattern_[1]};
#else
    const int pattern[2] = {};
#endif
    for (; n >= kBlock; n -= kBlock, p += kBlock * C) store_row_pattern(p, pattern);
    if (n > 0) copy_run(p, row_bytes_, n * C);
  }

  // A full block row of the flat colour. From registers: loading the pattern after each store would make
  // the load wait on the store whenever their addresses agree modulo 4 KiB.
  template <typename Pattern>
  void store_row_pattern(std::uint8_t* row, const Pattern (&pattern)[2]) const {
#if defined(__SSE2__)
    if constexpr (C == 3 || C == 4) {
      const __m128i a = pattern[0], b = pattern[1];
      _mm_storeu_si128(reinterpret_cast<__m128i*>(row), a);
      if constexpr (C == 4)
        _mm_storeu_si128(reinterpret_cast<__m128i*>(row + 16), b);
      else
        _mm_storel_epi64(reinterpret_cast<__m128i*>(row + 16), b);
      return;
    }
#endif
    std::memcpy(row, row_bytes_, kBlock * C);
  }

  // Copies the first `n` bytes (1 <= n <= 32) of `src` (which `dst` does not overlap) with two fixed-size
  // moves that may overlap each other (the same bytes go to the same places twice), instead of a call for a
  // variable length.
  static void copy_run(std::uint8_t* dst, const std::uint8_t* src, int n) {
    auto move = [&](int at, auto size) { std::memcpy(dst + at, src + at, decltype(size)::value); };
    using S1 = std::integral_constant<int, 1>;
    using S4 = std::integral_constant<int, 4>;
    using S8 = std::integral_constant<int, 8>;
    using S16 = std::integral_constant<int, 16>;
    if (n >= 16) {
      move(0, S16{}), move(n - 16, S16{});
    } else if (n >= 8) {
      move(0, S8{}), move(n - 8, S8{});
    } else if (n >= 4) {
      move(0, S4{}), move(n - 4, S4{});
    } else {
      for (int i = 0; i < n; ++i) move(i, S1{});
    }
  }

  // Colours interpolated in screen space (2D): channel = sum_k E_k v_k / area, rounded to nearest. Per
  // block, the value at its first pixel comes from the exact edge values and steps in 16.16 fixed point
  // across the block's rows and columns (at most 14 steps: an error below 10^-3 of a level, so a covered
  // pixel, whose exact value lies in the vertices' range, rounds into it). The block grid does not depend on
  // the tile, so neither does any pixel's value.
  void shade_smooth(const Block& b) const {
    if (steep_) return shade_smooth_exact(b);
    const double scale = 65536.0 / b.area;
    std::int64_t start[4];
    for (int ch = 0; ch < 4; ++ch) {
      const double n0 = b.e[0] * attr_[ch] + b.e[1] * attr_[4 + ch] + b.e[2] * attr_[8 + ch];
      start[ch] = floor_to_int(n0 * scale + 0.5) + 0x8000;
    }
#if defined(__SSE2__)
    if (fits_int32(start)) {
      if constexpr (C == 3 || C == 4)
        if (!mode_.blend) return shade_smooth_rows(b, start);
      return shade_smooth_lanes(b, start);
    }
#endif
    for (int r = 0; r < kBlock; ++r) {
      unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (!bits) continue;
      std::uint8_t* row = pixel(b.x0, b.y0 + r);
      for (; bits; bits &= bits - 1) {
        const int i = std::countr_zero(bits);
        std::uint8_t out[4];
        for (int ch = 0; ch < 4; ++ch) {
          const std::int64_t v = (start[ch] + i * slope_x_[ch] + r * slope_y_[ch]) >> 16;
          out[ch] = static_cast<std::uint8_t>(std::clamp<std::int64_t>(v, 0, 255));
        }
        write(row + i * C, Rgba8{out[0], out[1], out[2], out[3]});
      }
    }
  }

  // Every value the block can reach fits an int32 lane.
  bool fits_int32(const std::int64_t (&start)[4]) const {
    for (int ch = 0; ch < 4; ++ch)
      if (std::abs(start[ch]) + 8 * (std::abs(slope_x_[ch]) + std::abs(slope_y_[ch])) >= (std::int64_t{1} << 31))
        return false;
    return true;
  }

#if defined(__SSE2__)
  // The four channels of a pixel in the four lanes of one register: a pixel is an add, a shift and two
  // saturating packs. A row's covered pixels are one run (a triangle is convex, and so is the clip), so an
  // opaque run stores whole words: each pixel's spare byte is overwritten by the next pixel, the run's last
  // pixel is stored exactly.
  // Opaque RGB(A): the pixels of a row in the lanes, one register of four per channel and half row, stepped
  // down the block; a row's words are the channels' bytes side by side (a covered pixel's values lie in
  // 0..255, see shade_smooth, so its bytes cannot spill into each other; other lanes are not stored).
  void shade_smooth_rows(const Block& b, const std::int64_t (&start)[4]) const {
    __m128i left[C], four[C], down[C];
    for (int ch = 0; ch < C; ++ch) {
      const auto v = static_cast<std::int32_t>(start[ch]), d = static_cast<std::int32_t>(slope_x_[ch]);
      left[ch] = _mm_setr_epi32(v, v + d, v + 2 * d, v + 3 * d);
      four[ch] = _mm_set1_epi32(4 * d);
      down[ch] = _mm_set1_epi32(static_cast<std::int32_t>(slope_y_[ch]));
    }
    for (int r = 0; r < kBlock; ++r) {
      const unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (bits) {
        __m128i lo = _mm_setzero_si128(), hi = _mm_setzero_si128();
        for (int ch = 0; ch < C; ++ch) {
          const __m128i right = _mm_add_epi32(left[ch], four[ch]);
          lo = _mm_or_si128(lo, _mm_slli_epi32(_mm_srli_epi32(left[ch], 16), 8 * ch));
          hi = _mm_or_si128(hi, _mm_slli_epi32(_mm_srli_epi32(right, 16), 8 * ch));
        }
        std::uint8_t* p = pixel(b.x0, b.y0 + r);
        if (bits == 0xff) {
          store_full_row(p, lo, hi);
        } else {
          // Words straight from the registers (a trip through memory stalls store forwarding).
          const std::uint64_t q[4] = {
              static_cast<std::uint64_t>(_mm_cvtsi128_si64(lo)),
              static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_srli_si128(lo, 8))),
              static_cast<std::uint64_t>(_mm_cvtsi128_si64(hi)),
              static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_srli_si128(hi, 8)))};
          for (unsigned m = bits; m; m &= m - 1) {
            const int i = std::countr_zero(m);
            const auto word = static_cast<std::uint32_t>(q[i >> 1] >> (32 * (i & 1)));
            std::memcpy(p + C * i, &word, C);
          }
        }
      }
      for (int ch = 0; ch < C; ++ch) left[ch] = _mm_add_epi32(left[ch], down[ch]);
    }
  }

  // Eight pixels' words (four in each register) stored as a block row of C bytes a pixel. RGB: each 64-bit
  // half becomes two pixels' six bytes side by side; nothing past the row is written.
  static void store_full_row(std::uint8_t* p, __m128i lo, __m128i hi) {
    if constexpr (C == 4) {
      _mm_storeu_si128(reinterpret_cast<__m128i*>(p), lo);
      _mm_storeu_si128(reinterpret_cast<__m128i*>(p + 16), hi);
    } else {
      const __m128i even = _mm_set_epi32(0, 0xffffff, 0, 0xffffff), odd = _mm_set_epi32(0xffffff, 0, 0xffffff, 0);
      auto six = [&](__m128i w) { return _mm_or_si128(_mm_and_si128(w, even), _mm_srli_epi64(_mm_and_si128(w, odd), 8)); };
      const __m128i a = six(lo), b = six(hi);
      _mm_storel_epi64(reinterpret_cast<__m128i*>(p), a);
      _mm_storel_epi64(reinterpret_cast<__m128i*>(p + 6), _mm_srli_si128(a, 8));
      _mm_storel_epi64(reinterpret_cast<__m128i*>(p + 12), b);
      const auto last = static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_srli_si128(b, 8)));
      std::memcpy(p + 18, &last, 6);
    }
  }

  void shade_smooth_lanes(const Block& b, const std::int64_t (&start)[4]) const {
    __m128i row_value = _mm_setr_epi32(static_cast<int>(start[0]), static_cast<int>(start[1]),
                                       static_cast<int>(start[2]), static_cast<int>(start[3]));
    const __m128i step_x = _mm_setr_epi32(static_cast<int>(slope_x_[0]), static_cast<int>(slope_x_[1]),
                                          static_cast<int>(slope_x_[2]), static_cast<int>(slope_x_[3]));
    const __m128i step_y = _mm_setr_epi32(static_cast<int>(slope_y_[0]), static_cast<int>(slope_y_[1]),
                                          static_cast<int>(slope_y_[2]), static_cast<int>(slope_y_[3]));
    auto bytes = [](__m128i v) {
      const __m128i words = _mm_packs_epi32(_mm_srai_epi32(v, 16), _mm_setzero_si128());
      return static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_packus_epi16(words, words)));
    };
    auto color = [](std::uint32_t rgba) {
      return Rgba8{static_cast<std::uint8_t>(rgba), static_cast<std::uint8_t>(rgba >> 8),
                   static_cast<std::uint8_t>(rgba >> 16), static_cast<std::uint8_t>(rgba >> 24)};
    };
    for (int r = 0; r < kBlock; ++r, row_value = _mm_add_epi32(row_value, step_y)) {
      const unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (!bits) continue;
      const int lo = std::countr_zero(bits), hi = 31 - std::countl_zero(bits);
      std::uint8_t* p = pixel(b.x0 + lo, b.y0 + r);
      __m128i v = row_value;
      for (int i = 0; i < lo; ++i) v = _mm_add_epi32(v, step_x);
      const bool run = (bits >> lo) + 1 == 1u << (hi - lo + 1);
      if ((C == 3 || C == 4) && run && !mode_.blend) {
        for (int i = lo; i < hi; ++i, p += C, v = _mm_add_epi32(v, step_x)) {
          const std::uint32_t rgba = bytes(v);
          std::memcpy(p, &rgba, 4);
        }
        store<C>(p, color(bytes(v)));
        continue;
      }
      for (int i = lo; i <= hi; ++i, p += C, v = _mm_add_epi32(v, step_x))
        if (bits & (1u << i)) write(p, color(bytes(v)));
    }
  }
#endif

  // The same value without stepping, for triangles whose colour changes by more than 2^24 levels a pixel
  // (slivers): eight lanes of exact doubles per row.
  void shade_smooth_exact(const Block& b) const {
    using D8 = double __attribute__((vector_size(64)));
    const D8 lane = {0, 1, 2, 3, 4, 5, 6, 7};
    const double inv_area = 1.0 / b.area;
    for (int r = 0; r < kBlock; ++r) {
      unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (!bits) continue;
      double e[3];
      for (int k = 0; k < 3; ++k) e[k] = b.e[k] + r * b.dy[k];
      std::uint8_t out[4][8] = {};
      for (int ch = 0; ch < 4; ++ch) {
        if (!stores(ch)) continue;
        const double v0 = attr_[ch], v1 = attr_[4 + ch], v2 = attr_[8 + ch];
        const double n0 = e[0] * v0 + e[1] * v1 + e[2] * v2;
        const double dn = b.dx[0] * v0 + b.dx[1] * v1 + b.dx[2] * v2;
        D8 value = (n0 + lane * dn) * inv_area + 0.5;
        value = value < lo_[ch] ? lo_[ch] : value;
        value = value > hi_[ch] + 0.5 ? hi_[ch] + 0.5 : value;  // stays below hi + 1 after flooring
        for (int i = 0; i < 8; ++i) out[ch][i] = static_cast<std::uint8_t>(static_cast<int>(value[i]));
      }
      std::uint8_t* row = pixel(b.x0, b.y0 + r);
      for (; bits; bits &= bits - 1) {
        const int i = std::countr_zero(bits);
        write(row + i * C, Rgba8{out[0][i], out[1][i], out[2][i], out[3][i]});
      }
    }
  }

  // The channels a format of C channels stores (grey r, grey+alpha r and a, RGB, RGBA), and alpha when
  // it weighs a blend.
  bool stores(int ch) const {
    if (ch == 3) return C == 2 || C == 4 || mode_.blend;
    if (ch == 0) return true;
    return C >= 3;
  }

  // 3D: depth test (reversed: larger is nearer; ties keep what was drawn first), then perspective-correct
  // colour and, when lit per pixel, the interpolated normal's Lambert term.
  void shade_depth(const Block& b) const {
    const double inv_area = 1.0 / b.area;
    const float* z = depth_at_;
    for (int r = 0; r < kBlock; ++r) {
      unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (!bits) continue;
      const std::size_t row = surface_.index(b.x0, b.y0 + r);
      for (; bits; bits &= bits - 1) {
        const int i = std::countr_zero(bits);
        // screen-space barycentrics; depth (z / w) is affine in screen space
        const double l[3] = {(b.e[0] + i * b.dx[0] + r * b.dy[0]) * inv_area,
                             (b.e[1] + i * b.dx[1] + r * b.dy[1]) * inv_area,
                             (b.e[2] + i * b.dx[2] + r * b.dy[2]) * inv_area};
        const float depth = static_cast<float>(l[0] * z[0] + l[1] * z[1] + l[2] * z[2]);
        float& stored = surface_.depth[row + i];
        if (!(depth > stored)) continue;
        stored = depth;
        std::uint8_t* p = surface_.color + (row + i) * C;
        if (!mode_.smooth) {
          write(p, flat_);
          continue;
        }
        write(p, smooth_color(l));
      }
    }
  }

  Rgba8 smooth_color(const double (&l)[3]) const {
    // perspective-correct weights: interpolate attribute / w and 1 / w, then divide
    double q[3], sum = 0;
    for (int k = 0; k < 3; ++k) sum += q[k] = l[k] * inv_w_at_[k];
    for (double& qk : q) qk /= sum;
    double rgba[4];
    if (mode_.varying_color)
      for (int c = 0; c < 4; ++c) rgba[c] = q[0] * attr_[c] + q[1] * attr_[4 + c] + q[2] * attr_[8 + c];
    else
      for (int c = 0; c < 4; ++c) rgba[c] = attr_[c];
    if (uv_at_) texture(l, sum, rgba);
    if (normal_at_) {
      const float* n = normal_at_;
      double nrm[3], p[3] = {0, 0, 0}, shade[3];
      for (int c = 0; c < 3; ++c) nrm[c] = q[0] * n[c] + q[1] * n[3 + c] + q[2] * n[6 + c];
      const double len = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
      // A degenerate interpolated normal (opposite vertex normals cancelling) gets the ambient light only.
      const double scale = len > 0 ? flip_ / len : 0;
      for (double& c : nrm) c *= scale;
      if (position_at_)
        for (int c = 0; c < 3; ++c)
          p[c] = q[0] * position_at_[c] + q[1] * position_at_[3 + c] + q[2] * position_at_[6 + c];
      light_at(call_.lights, nrm, p, shade);
      for (int c = 0; c < 3; ++c) rgba[c] *= shade[c];
    }
    return {to_byte(rgba[0]), to_byte(rgba[1]), to_byte(rgba[2]), to_byte(rgba[3])};
  }

  // Multiplies `rgba` by the texture at the perspective-correct coordinates of barycentrics `l` (sum: their
  // 1/w-weighted sum). The level of detail comes from the exact screen derivatives of u / w over 1 / w.
  void texture(const double (&l)[3], double sum, double (&rgba)[4]) const {
    const float* uv = uv_at_;
    double u = 0, v = 0, su_x = 0, sv_x = 0, su_y = 0, sv_y = 0, s_x = 0, s_y = 0;
    for (int k = 0; k < 3; ++k) {
      const double w = inv_w_at_[k], wu = w * uv[2 * k], wv = w * uv[2 * k + 1];
      u += l[k] * wu, v += l[k] * wv;
      su_x += dl_dx_[k] * wu, sv_x += dl_dx_[k] * wv, s_x += dl_dx_[k] * w;
      su_y += dl_dy_[k] * wu, sv_y += dl_dy_[k] * wv, s_y += dl_dy_[k] * w;
    }
    u /= sum, v /= sum;
    const MipChain& tex = *call_.texture;
    const double sx = tex.texture->scale[0], sy = tex.texture->scale[1];
    const double lod = mip_lod((su_x - u * s_x) / sum * sx, (sv_x - v * s_x) / sum * sy, (su_y - u * s_y) / sum * sx,
                               (sv_y - v * s_y) / sum * sy, tex.levels[0].width, tex.levels[0].height);
    float texel[4];
    tex.sample(u, v, lod, texel);
    for (int c = 0; c < 4; ++c) rgba[c] *= texel[c];
  }

  const DrawCall& call_;
  const PrimitivePlan mode_;
  const float* attr_;
  const Surface& surface_;
  const double flip_;  // two-sided lighting: a back face is lit from the side seen
  const bool union_;   // area coverage of a multi-triangle primitive: accumulated, composited at its end
  const bool msaa_;    // multisampling: samples() and whole() keep the pixels' samples
  float z_offset_[16] = {};  // 3D multisampling: each sample's depth minus the pixel centre's
  const float* depth_at_ = nullptr;
  const float* inv_w_at_ = nullptr;
  const float* normal_at_ = nullptr;
  const float* position_at_ = nullptr;  // lit by a point light per pixel: 3 x world xyz
  const float* uv_at_ = nullptr;  // textured calls with a texture: 3 x (u, v)
  double dl_dx_[3] = {}, dl_dy_[3] = {};  // textured: barycentric change per pixel right and down
  Rgba8 flat_;
  enum class Kind : std::uint8_t { flat, smooth, depth } kind_ = Kind::flat;
  std::uint8_t row_bytes_[32] = {};  // flat: a block row of the colour, stored (kBlock * C bytes used)
#if defined(__SSE2__)
  __m128i pattern_[2] = {};  // the same 32 bytes in registers' form
#endif
  double lo_[4] = {}, hi_[4] = {};
  std::int64_t slope_x_[4] = {}, slope_y_[4] = {};  // 16.16 per pixel right and down
  bool steep_ = false;  // some slope beyond 2^24 levels a pixel: no fixed-point stepping
};

}  // namespace raster::detail
