// Shade: covered blocks (coverage.h) + a triangle or quad record's attributes -> pixels. With fill.h (the
// 2D colour kernels), perspective.h (3D varyings) and plan/light.h (Lambert, specular), where a triangle's
// colour per pixel is computed: interpolation of the attribute planes, perspective correction, lighting per
// pixel, textures, depth and samples; framebuffer/pixel.h writes it. (Flat-lit faces get their one colour
// from plan/light.h in geometry, per face; 1-px lines and points are written by coverage/line.cpp and
// point.cpp in their records' colours.)
// Templated on the framebuffer's channel count so the per-pixel code has no format branches.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>

#include "base/lanes.h"
#include "coverage/coverage.h"
#include "raster/image.h"
#include "raster/scene.h"
#include "setup/setup.h"
#include "shade/fill.h"
#include "shade/perspective.h"
#include "shade/resolve.h"

namespace raster::detail {

/// Shades the blocks of one triangle record inside one tile. Made per record per tile: everything that
/// depends only on the record is worked out here, once, not per block. A line's quad (setup.h QuadRecord)
/// is shaded by it too: its call is flat, so only its colour row is read.
template <int C>
class TriangleShader {
 public:
  /// `step_x` and `step_y` are the record's edge-value steps per pixel right and down (256 a_k, 256 b_k) and
  /// `area` its doubled area, as doubles (exact for the fast range); `back_facing`: 3D, seen from behind.
  TriangleShader(const DrawCall& call, bool back_facing, const float* attributes, const Surface& surface,
                 const double (&step_x)[3], const double (&step_y)[3], double area)
      : mode_(call.mode),
        attr_(attributes),
        surface_(surface),
        union_(call.mode.union_coverage && surface.coverage_mode == Coverage::area),
        msaa_(surface.coverage_mode == Coverage::samples) {
    // Vertex k's value of each varying in the record, or nullptr when it has none.
    const VaryingLayout& with = call.layout;
    const float* at[kVaryingCount][3] = {};
    for (int i = 0; i < kVaryingCount; ++i)
      if (with.vertex_offset[i] >= 0)
        for (int k = 0; k < 3; ++k) at[i][k] = attr_ + with.record_at(static_cast<Varying>(i), k);
    const float* c = at[static_cast<int>(Varying::color)][0];
    flat_ = {to_byte(c[0]), to_byte(c[1]), to_byte(c[2]), to_byte(c[3])};
    const float* const* depth = at[static_cast<int>(Varying::depth)];
    if (depth[0]) depth_[0] = *depth[0], depth_[1] = *depth[1], depth_[2] = *depth[2];
    if (depth[0]) {
      // The planes' steps per pixel right and down: depth (doubles), the barycentrics (floats), and the
      // first at a block row's eight columns.
      double dl_dx[3], dl_dy[3], dz_dx = 0;
      const double inv_area = 1.0 / area;  // one division a record, not six
      for (int k = 0; k < 3; ++k) {
        dl_dx[k] = step_x[k] * inv_area, dl_dy[k] = step_y[k] * inv_area;
        dz_dx += dl_dx[k] * depth_[k], dz_dy_ += dl_dy[k] * depth_[k];
        dl_dy_[k] = static_cast<float>(dl_dy[k]);
        l_columns_[k] = kColumns * static_cast<float>(dl_dx[k]);
      }
      z_columns_[0] = kLeftColumns * dz_dx, z_columns_[1] = kRightColumns * dz_dx;
      if (mode_.smooth) std::construct_at(&kernel_.color, call, at, back_facing ? -1.0f : 1.0f, dl_dx, dl_dy);
      // Multisampled: depth is affine in screen space, so each sample's z is the centre's plus a constant.
      if (msaa_)
        for (int s = 0; s < surface.sample_count; ++s)
          z_offset_[s] = static_cast<float>(dz_dx * (surface.pattern[s].x - 128) / 256.0 +
                                            dz_dy_ * (surface.pattern[s].y - 128) / 256.0);
    }

    kind_ = depth[0] ? Kind::perspective : mode_.smooth ? Kind::smooth : Kind::flat;
    if (kind_ == Kind::flat) std::construct_at(&kernel_.fill, surface, flat_, mode_.blend);
    if (kind_ == Kind::smooth)
      std::construct_at(&kernel_.planes, surface, at[static_cast<int>(Varying::color)], step_x, step_y, area,
                        mode_.blend);
  }

  /// Every pixel of `clip` is covered; `first` is the block at the clip's block-grid origin (its mask is
  /// all ones, its values exact). Flat opaque colour fills the rows as long runs; anything else is shaded
  /// block by block with exactly the values the blocks would have had.
  void rect(Rect clip, const Block& first) {
    if (kind_ == Kind::flat && !mode_.blend && !union_) {
      for (int y = clip.y0; y < clip.y1; ++y)
        kernel_.fill.run(surface_.pixel<C>(clip.x0, y), clip.x1 - clip.x0);
      if (msaa_) {  // every sample of these pixels now holds the colour: one value each again
        for_each_block(clip, first,
                       [&](const Block& b) { surface_.template one_colour<C>(b.x0, b.y0, b.mask); });
        *surface_.shaded += std::int64_t{clip.x1 - clip.x0} * (clip.y1 - clip.y0);
      }
      return;
    }
    if (kind_ == Kind::smooth && !union_ && !msaa_) return kernel_.planes.rect(clip, first);
    for_each_block(clip, first, [&](const Block& b) { (*this)(b); });
  }

  void operator()(const Block& b) {
    if (union_) return accumulate(b, nullptr);
    if (msaa_) return whole(b);
    shade_aliased(b);
  }

  /// Multisampling: `masks[s]` are the pixels whose sample s is covered, `b.mask` their union, and
  /// masks[sample_count] the pixels whose centre is covered. Each pixel is shaded once (at its centre, or at
  /// the centroid of its covered samples when the centre is outside) and the colour goes to the covered
  /// samples; whole pixels take the aliased path.
  void samples(const Block& b, const std::uint64_t* masks) {
    const int n = surface_.sample_count;
    if (kind_ == Kind::perspective) return depth_samples(b, masks);
    std::uint64_t all = b.mask;
    for (int s = 0; s < n; ++s) all &= masks[s];
    if (all) {
      Block w = b;
      w.mask = all;
      whole(w);
    }
    std::uint64_t& expanded = surface_.expanded_bits(b.x0, b.y0);
    const std::uint64_t partial = b.mask & ~all;
    if (kind_ == Kind::flat && !mode_.blend) {
      // One colour, stored: sample plane by sample plane, with no pixel's samples gathered.
      for (std::uint64_t m = partial & ~expanded; m; m &= m - 1)
        surface_.template expand<C>(
            surface_.index(b.x0 + (std::countr_zero(m) & 7), b.y0 + (std::countr_zero(m) >> 3)));
      expanded |= partial;
      const std::size_t first = surface_.index(b.x0, b.y0);
      for (int s = 0; s < n; ++s) {
        std::uint8_t* plane = surface_.template sample_pixel<C>(s, first);
        for (std::uint64_t m = masks[s] & partial; m; m &= m - 1) {
          const int bit = std::countr_zero(m);
          store<C>(plane + (static_cast<std::size_t>(bit >> 3) * surface_.width + (bit & 7)) * C, flat_);
        }
      }
      *surface_.shaded += std::popcount(partial);
      return;
    }
    for (std::uint64_t m = partial; m; m &= m - 1) {
      const int bit = std::countr_zero(m), i = bit & 7, r = bit >> 3;
      const unsigned covered = covered_samples(masks, bit);
      const Rgba8 c = color_at(b, i, r, covered);
      const std::size_t index = surface_.index(b.x0 + i, b.y0 + r);
      if (!((expanded >> bit) & 1)) surface_.template expand<C>(index), expanded |= std::uint64_t{1} << bit;
      for (unsigned k = covered; k; k &= k - 1)
        put<C>(surface_.template sample_pixel<C>(std::countr_zero(k), index), c, mode_.blend);
    }
    *surface_.shaded += std::popcount(partial);
  }

  void shade_aliased(const Block& b) {
    switch (kind_) {
      case Kind::flat:
        return kernel_.fill.block(b);
      case Kind::smooth:
        return kernel_.planes.block(b);
      case Kind::perspective:
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
      blend_weighted<C>(surface_.pixel<C>(b.x0 + i, b.y0 + r), c, cut.share[bit] * (c.a / 255.0f));
    }
  }

 private:
  // Multisampling, pixels with every sample covered (2D). Opaque stores make a pixel's samples one colour
  // again; blending keeps them apart, each sample blended.
  void whole(const Block& b) {
    if (kind_ == Kind::perspective) {
      std::uint64_t masks[17];  // every sample and every centre covered
      std::fill_n(masks, surface_.sample_count + 1, b.mask);
      return depth_samples(b, masks);
    }
    std::uint64_t& expanded = surface_.expanded_bits(b.x0, b.y0);
    *surface_.shaded += std::popcount(b.mask);
    if (!mode_.blend) {
      shade_aliased(b);
      return surface_.template one_colour<C>(expanded, b.x0, b.y0, b.mask);
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
      for (int s = 0; s < surface_.sample_count; ++s)
        blend<C>(surface_.template sample_pixel<C>(s, index), c);
    }
  }

  // 3D multisampling: depth tested per sample (the plane at each position), shaded once per pixel; a block
  // row at a time in lanes, on the plan's instruction set.
  // A mesh with cut-outs (PrimitivePlan::cut_outs) takes its own instantiation: the others keep the code
  // that writes depth as it tests, with no cost for the case they never have.
  void depth_samples(const Block& b, const std::uint64_t* masks) {
#if defined(__x86_64__)
    if (surface_.simd == Simd::avx2)
      return mode_.cut_outs ? depth_samples_avx2<true>(b, masks) : depth_samples_avx2<false>(b, masks);
#endif
    mode_.cut_outs ? depth_samples_lanes<true>(b, masks) : depth_samples_lanes<false>(b, masks);
  }
#if defined(__x86_64__)
  template <bool kCutOuts>
  __attribute__((target("avx2"))) void depth_samples_avx2(const Block& b, const std::uint64_t* masks) {
    depth_samples_lanes<kCutOuts>(b, masks);
  }
#endif

  // kCutOuts: the row is shaded before any depth is written, and the pixels whose alpha comes out 0 are
  // taken out of every sample's pass, so a cut-out texel keeps neither colour nor depth.
  template <bool kCutOuts>
  [[gnu::always_inline]] inline void depth_samples_lanes(const Block& b, const std::uint64_t* masks) {
    const int n = surface_.sample_count;
    const unsigned all = (1u << n) - 1;
    double z0;
    float l0[3];
    block_start(b, z0, l0);
    std::uint64_t& expanded = surface_.expanded_bits(b.x0, b.y0);
    for (int r = 0; r < kBlock; ++r) {
      const unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (!bits) continue;
      FloatLanes centre;
      row_depth(z0, r, centre);
      const std::size_t at = surface_.index(b.x0, b.y0 + r);
      // Per sample, the depth test of the row's pixels whose sample s is covered.
      unsigned pass[16], any = 0;
      for (int s = 0; s < n; ++s) {
        const unsigned covered = static_cast<unsigned>(masks[s] >> (8 * r)) & 0xff;
        float* stored = surface_.depth + static_cast<std::size_t>(s) * surface_.plane + at;
        if constexpr (kCutOuts)
          pass[s] = covered ? nearer(stored, centre + z_offset_[s], covered) : 0;
        else
          pass[s] = covered ? depth_test(stored, centre + z_offset_[s], covered) : 0;
        any |= pass[s];
      }
      if (!any) continue;
      FloatLanes rgba[4] = {};
      if constexpr (kCutOuts) {
        // Shaded at every pixel that passed somewhere (the centroid moves nothing where all samples are
        // covered, so the colours are those the other path gives); alpha 0 drops the pixel from each sample.
        unsigned visible = flat_.a ? 0xffu : 0u;
        if (mode_.smooth) {
          shade_row(b, masks, r, l0, any, any, rgba);
          visible = lane_bits(rgba[3] >= 1.0f);  // byte_lanes: the alpha byte is 0 below 1
        }
        if (!(any = keep_visible(centre, at, visible, pass))) continue;
      }
      *surface_.shaded += std::popcount(any);
      // Pixels whose every sample passed: one colour again, written as an aliased row writes it.
      unsigned whole = mode_.blend ? 0u : any;
      for (int s = 0; s < n; ++s) whole &= pass[s];
      std::uint8_t* p = surface_.color + at * C;
      std::uint64_t r8 = 0, g8 = 0, b8 = 0, a8 = 0;  // the pixels' colours, byte i for lane i
      if (mode_.smooth) {
        if constexpr (!kCutOuts) shade_row(b, masks, r, l0, any, any & ~whole, rgba);
        if (whole) write(p, whole, rgba);
        r8 = lane_bytes(rgba[0]), a8 = lane_bytes(rgba[3]);
        g8 = kColours == 3 ? lane_bytes(rgba[1]) : r8, b8 = kColours == 3 ? lane_bytes(rgba[2]) : r8;
      } else {
        for (unsigned m = whole; m; m &= m - 1) store<C>(p + std::countr_zero(m) * C, flat_);
      }
      if (whole) surface_.template one_colour<C>(expanded, b.x0, b.y0, std::uint64_t{whole} << (8 * r));
      for (unsigned m = any & ~whole; m; m &= m - 1) {
        const int i = std::countr_zero(m), bit = 8 * r + i, shift = 8 * i;
        const std::size_t index = at + static_cast<std::size_t>(i);
        unsigned passed = 0;
        for (int s = 0; s < n; ++s) passed |= ((pass[s] >> i) & 1u) << s;
        const Rgba8 c =
            mode_.smooth
                ? Rgba8{static_cast<std::uint8_t>(r8 >> shift), static_cast<std::uint8_t>(g8 >> shift),
                        static_cast<std::uint8_t>(b8 >> shift), static_cast<std::uint8_t>(a8 >> shift)}
                : flat_;
        if (passed == all && !mode_.blend) {
          store<C>(surface_.color + index * C, c);
          surface_.template one_colour<C>(expanded, b.x0, b.y0, std::uint64_t{1} << bit);
          continue;
        }
        if (!((expanded >> bit) & 1)) {
          if (passed == all) {  // blending over a pixel whose samples agree: still one colour
            blend<C>(surface_.color + index * C, c);
            continue;
          }
          surface_.template expand<C>(index), expanded |= std::uint64_t{1} << bit;
        }
        for (unsigned k = passed; k; k &= k - 1)
          put<C>(surface_.template sample_pixel<C>(std::countr_zero(k), index), c, mode_.blend);
      }
    }
  }

  // The colours (byte_lanes values) of the lanes `lanes` of block row r, each shaded at its pixel's centre,
  // or for those of `moved` at the centroid of its covered samples where the centre is not covered.
  [[gnu::always_inline]] inline void shade_row(const Block& b, const std::uint64_t* masks, int r,
                                               const float (&l0)[3], unsigned lanes, unsigned moved,
                                               FloatLanes (&rgba)[4]) const {
    FloatLanes l[3];
    for (int k = 0; k < 3; ++k) l[k] = (l0[k] + static_cast<float>(r) * dl_dy_[k]) + l_columns_[k];
    if (moved) centroids(b, r, masks, moved, l);
    kernel_.color.template shade<kColours>(l, lanes, rgba);
    for (FloatLanes& v : rgba) byte_lanes(v);
  }

  // Multisampled cut-outs: the lanes not in `visible` leave every sample's pass (of the block row at `at`,
  // depth `centre` at the pixel centres), and the others' depth is written. Returns the lanes still passing.
  [[gnu::always_inline]] inline unsigned keep_visible(const FloatLanes& centre, std::size_t at,
                                                      unsigned visible, unsigned* pass) const {
    unsigned any = 0;
    for (int s = 0; s < surface_.sample_count; ++s) {
      if ((pass[s] &= visible))
        keep_depth(surface_.depth + static_cast<std::size_t>(s) * surface_.plane + at, centre + z_offset_[s],
                   pass[s]);
      any |= pass[s];
    }
    return any;
  }

  // The depth test of the lanes of `covered` against the stored row at `stored`: nearer values are kept;
  // returns the lanes that passed.
  [[gnu::always_inline]] inline static unsigned depth_test(float* stored, const FloatLanes& depth,
                                                           unsigned covered) {
    FloatLanes old;
    std::memcpy(&old, stored, sizeof old);
    const IntLanes nearer = (depth > old) & ((kLaneBit & static_cast<std::int32_t>(covered)) != 0);
    const unsigned pass = lane_bits(nearer);
    if (pass) {
      const FloatLanes kept = nearer ? depth : old;
      std::memcpy(stored, &kept, sizeof kept);
    }
    return pass;
  }
  // depth_test in two steps, for meshes with cut-outs: the lanes of `covered` nearer than the stored row
  // (nothing written), then the depth of the lanes of `lanes` written once their alpha is known.
  [[gnu::always_inline]] inline static unsigned nearer(const float* stored, const FloatLanes& depth,
                                                       unsigned covered) {
    FloatLanes old;
    std::memcpy(&old, stored, sizeof old);
    return lane_bits((depth > old) & ((kLaneBit & static_cast<std::int32_t>(covered)) != 0));
  }
  [[gnu::always_inline]] inline static void keep_depth(float* stored, const FloatLanes& depth,
                                                       unsigned lanes) {
    FloatLanes old;
    std::memcpy(&old, stored, sizeof old);
    const FloatLanes kept = (kLaneBit & static_cast<std::int32_t>(lanes)) != 0 ? depth : old;
    std::memcpy(stored, &kept, sizeof kept);
  }

  // A block's values at its first pixel, from its exact edge values: depth in doubles, the barycentrics in
  // floats. The lanes step from them (row_depth, l_columns_), so a pixel's values depend on its block only,
  // never on the tile or on whether the walker or rect() reached it.
  void block_start(const Block& b, double& z0, float (&l0)[3]) const {
    const double inv_area = 1.0 / b.area;
    z0 = 0;
    for (int k = 0; k < 3; ++k) {
      const double l = b.e[k] * inv_area;
      z0 += l * depth_[k];
      l0[k] = static_cast<float>(l);
    }
  }
  // Depth at the pixel centres of row r, rounded once to the float the depth buffer holds.
  [[gnu::always_inline]] inline void row_depth(double z0, int r, FloatLanes& depth) const {
    const double z_row = z0 + r * dz_dy_;
    const FloatHalf left = __builtin_convertvector(z_row + z_columns_[0], FloatHalf);
    const FloatHalf right = __builtin_convertvector(z_row + z_columns_[1], FloatHalf);
    depth = __builtin_shufflevector(left, right, 0, 1, 2, 3, 4, 5, 6, 7);
  }

  // 3D multisampling moves the shading point of the lanes of `moved` whose pixel centre the triangle does
  // not cover (masks[n], the centres' mask) to the centroid of their covered samples, to the bits
  // shading_point gives: the offsets from the pattern's table, the three divisions in one vector.
  [[gnu::always_inline]] inline void centroids(const Block& b, int r, const std::uint64_t* masks,
                                               unsigned moved, FloatLanes (&l)[3]) const {
    const int n = surface_.sample_count;
    const unsigned all = (1u << n) - 1;
    for (unsigned m = moved & ~static_cast<unsigned>(masks[n] >> (8 * r)) & 0xffu; m; m &= m - 1) {
      const int i = std::countr_zero(m);
      const unsigned covered = covered_samples(masks, 8 * r + i);
      if (covered == all) continue;
      double cx, cy;
      centroid_offset(covered, cx, cy);
      const DoubleHalf change = DoubleHalf{cx * b.dx[0] + cy * b.dy[0], cx * b.dx[1] + cy * b.dy[1],
                                           cx * b.dx[2] + cy * b.dy[2], 0} /
                                b.area;
      for (int k = 0; k < 3; ++k) l[k][i] += static_cast<float>(change[k]);
    }
  }

  // The samples of pixel `bit` of a block that the triangle covers: bit s for sample s.
  [[gnu::always_inline]] inline unsigned covered_samples(const std::uint64_t* masks, int bit) const {
    unsigned covered = 0;
    for (int s = 0; s < surface_.sample_count; ++s)
      covered |= static_cast<unsigned>((masks[s] >> bit) & 1) << s;
    return covered;
  }

  // The centroid of the samples `covered` as (x, y) pixels from the pixel centre.
  [[gnu::always_inline]] inline void centroid_offset(unsigned covered, double& x, double& y) const {
    if (surface_.centroids) {
      x = surface_.centroids[covered][0], y = surface_.centroids[covered][1];
      return;
    }
    x = 0, y = 0;
    for (unsigned k = covered; k; k &= k - 1) {
      const SamplePoint p = surface_.pattern[std::countr_zero(k)];
      x += p.x - 128, y += p.y - 128;
    }
    const double count = std::popcount(covered) * 256.0;
    x /= count, y /= count;
  }

  // Where a pixel whose samples `covered` are covered is shaded: false for its centre, when the triangle
  // covers the centre (or every sample); else true, with the centroid of the covered samples as (x, y)
  // pixels from the centre.
  [[gnu::always_inline]] inline bool shading_offset(const Block& b, int i, int r, unsigned covered, double& x,
                                                    double& y) const {
    const unsigned all = (1u << surface_.sample_count) - 1;
    if (covered == all ||
        (!(b.e[0] + i * b.dx[0] + r * b.dy[0] < 0) && !(b.e[1] + i * b.dx[1] + r * b.dy[1] < 0) &&
         !(b.e[2] + i * b.dx[2] + r * b.dy[2] < 0)))
      return false;
    centroid_offset(covered, x, y);
    return true;
  }

  // Barycentric weights where a pixel is shaded (see shading_offset), in doubles: the 2D path's. `l` holds
  // the centre's on entry.
  void shading_point(const Block& b, int i, int r, unsigned covered, double (&l)[3]) const {
    double cx, cy;
    if (!shading_offset(b, i, r, covered, cx, cy)) return;
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
    return kernel_.planes.at(l);
  }

  // Union coverage: adds share (1 for whole pixels, `shares` for cut ones) and share x colour per pixel.
  void accumulate(const Block& b, const float* shares) const {
    surface_.expanded_bits(b.x0, b.y0) |= b.mask;
    for (std::uint64_t m = b.mask; m; m &= m - 1) {
      const int bit = std::countr_zero(m), i = bit & 7, r = bit >> 3;
      const Rgba8 c = color_at(b, i, r);
      const float share = shares ? shares[bit] : 1.0f;
      float* acc = surface_.coverage + surface_.index(b.x0 + i, b.y0 + r) * kUnionFloats;
      acc[0] += share, acc[1] += share * c.r, acc[2] += share * c.g, acc[3] += share * c.b,
          acc[4] += share * c.a;
    }
  }

  // 3D: depth test (reversed: larger is nearer; ties keep what was drawn first), then the colour of the
  // pixels that pass, eight at a time (a block row): on the plan's instruction set, the same bytes on each.
  // Cut-outs (PrimitivePlan::cut_outs) as depth_samples takes them: an instantiation of their own.
  void shade_depth(const Block& b) const {
#if defined(__x86_64__)
    if (surface_.simd == Simd::avx2)
      return mode_.cut_outs ? shade_depth_avx2<true>(b) : shade_depth_avx2<false>(b);
#endif
    mode_.cut_outs ? shade_depth_lanes<true>(b) : shade_depth_lanes<false>(b);
  }
#if defined(__x86_64__)
  template <bool kCutOuts>
  __attribute__((target("avx2"))) void shade_depth_avx2(const Block& b) const {
    shade_depth_lanes<kCutOuts>(b);
  }
#endif

  // kCutOuts: the lanes that pass are shaded before their depth is written; those whose alpha comes out 0
  // write neither.
  template <bool kCutOuts>
  [[gnu::always_inline]] inline void shade_depth_lanes(const Block& b) const {
    double z0;
    float l0[3];
    block_start(b, z0, l0);
    for (int r = 0; r < kBlock; ++r) {
      const unsigned bits = static_cast<unsigned>(b.mask >> (8 * r)) & 0xff;
      if (!bits) continue;
      const std::size_t at = surface_.index(b.x0, b.y0 + r);
      FloatLanes depth;
      row_depth(z0, r, depth);
      unsigned pass =
          kCutOuts ? nearer(surface_.depth + at, depth, bits) : depth_test(surface_.depth + at, depth, bits);
      if (!pass) continue;
      std::uint8_t* p = surface_.color + at * C;
      if (!mode_.smooth) {
        if constexpr (kCutOuts) {
          if (!flat_.a) continue;
          keep_depth(surface_.depth + at, depth, pass);
        }
        for (unsigned m = pass; m; m &= m - 1) put<C>(p + std::countr_zero(m) * C, flat_, mode_.blend);
        continue;
      }
      FloatLanes l[3], rgba[4] = {};
      for (int k = 0; k < 3; ++k) l[k] = (l0[k] + static_cast<float>(r) * dl_dy_[k]) + l_columns_[k];
      kernel_.color.template shade<kColours>(l, pass, rgba);
      for (FloatLanes& v : rgba) byte_lanes(v);
      if constexpr (kCutOuts) {
        if (!(pass &= lane_bits(rgba[3] >= 1.0f))) continue;  // byte_lanes: the alpha byte is 0 below 1
        keep_depth(surface_.depth + at, depth, pass);
      }
      write(p, pass, rgba);
    }
  }

  // Writes the lanes' colours (byte_lanes values) to the pixels of `pass` of the block row at `p`: opaque
  // grey as one masked word, others a pixel at a time from the packed bytes.
  [[gnu::always_inline]] inline void write(std::uint8_t* p, unsigned pass,
                                           const FloatLanes (&rgba)[4]) const {
    const std::uint64_t r = lane_bytes(rgba[0]);
    if constexpr (C == 1) {
      if (!mode_.blend) {
        std::uint64_t row, keep;
        std::memcpy(&row, p, sizeof row);
        std::memcpy(&keep, kByteMasks<1>[pass], sizeof keep);
        row = (row & ~keep) | (r & keep);
        std::memcpy(p, &row, sizeof row);
        return;
      }
    }
    const std::uint64_t g = kColours == 3 ? lane_bytes(rgba[1]) : r,
                        b = kColours == 3 ? lane_bytes(rgba[2]) : r;
    const std::uint64_t a = lane_bytes(rgba[3]);
    for (unsigned m = pass; m; m &= m - 1) {
      const int i = std::countr_zero(m), shift = 8 * i;
      const Rgba8 c{static_cast<std::uint8_t>(r >> shift), static_cast<std::uint8_t>(g >> shift),
                    static_cast<std::uint8_t>(b >> shift), static_cast<std::uint8_t>(a >> shift)};
      put<C>(p + i * C, c, mode_.blend);
    }
  }

  // Grey images compute one colour channel (their lights are grey).
  static constexpr int kColours = C >= 3 ? 3 : 1;
  static constexpr FloatLanes kColumns = {0, 1, 2, 3, 4, 5, 6, 7};
  static constexpr DoubleHalf kLeftColumns = {0, 1, 2, 3}, kRightColumns = {4, 5, 6, 7};

  const PrimitivePlan mode_;
  const float* attr_;
  const Surface& surface_;
  const bool union_;     // area coverage of a multi-triangle primitive: accumulated, composited at its end
  const bool msaa_;      // multisampling: samples() and whole() keep the pixels' samples
  float z_offset_[16];   // 3D multisampling: each sample's depth minus the pixel centre's
  float depth_[3] = {};  // 3D: each vertex's z / w
  // 3D aliased blocks: depth's change per pixel down and at each column of a block row (in two halves of
  // four), and the barycentrics' change per pixel down and at each column.
  // (Set by the constructor where used, not initialised: a dense mesh's record covers a pixel or two, and a
  // shader is made per record per tile.)
  double dz_dy_ = 0;
  DoubleHalf z_columns_[2];
  float dl_dy_[3];
  FloatLanes l_columns_[3];
  Rgba8 flat_;
  // flat: one colour; smooth: 2D per-vertex colours in screen space; perspective: the 3D path (depth-tested,
  // attributes interpolated perspective-correct, lit, textured)
  enum class Kind : std::uint8_t { flat, smooth, perspective } kind_ = Kind::flat;
  // The kind's kernel, the one member of this made by the constructor (each is trivially destructible).
  union Kernel {
    Kernel() {}
    FlatFill<C> fill;        // Kind::flat
    ColorPlanes<C> planes;   // Kind::smooth
    PerspectiveColor color;  // Kind::perspective, smooth
  } kernel_;
};

}  // namespace raster::detail
