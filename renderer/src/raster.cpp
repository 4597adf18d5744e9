#include "raster.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <utility>

#include "shade.h"
#include "wide.h"

namespace raster::detail {
namespace {

// Integer division rounding toward -infinity / +infinity (C++ '/' rounds toward zero). d > 0.
std::int64_t floor_div(std::int64_t n, std::int64_t d) {
  return n / d - ((n % d != 0) && (n < 0));
}
std::int64_t ceil_div(std::int64_t n, std::int64_t d) {
  return n / d + ((n % d != 0) && (n > 0));
}

// Writes `count` pixels from `p` on: one flat colour, or per pixel from `next_color()` (called in order).
template <int C, typename NextColor>
void shade_span(std::uint8_t* p, std::int64_t count, PrimitivePlan mode, Rgba8 flat, NextColor&& next_color) {
  std::uint8_t* const end = p + count * C;
  if (!mode.smooth) {
    if (mode.blend) {
      for (; p != end; p += C) blend<C>(p, flat);
    } else {
      for (; p != end; p += C) store<C>(p, flat);
    }
    return;
  }
  for (; p != end; p += C) {
    const Rgba8 c = next_color();
    if (mode.blend)
      blend<C>(p, c);
    else
      store<C>(p, c);
  }
}

// ---- Triangles, fast path: int64 edge functions on the 1/256 px grid ------------------------------------

// floor(n / d) for a numerator that changes by a constant each step, kept exactly without dividing per
// step: n = q d + r with 0 <= r < d, and the change split the same way (Bresenham's trick).
struct FloorStepper {
  std::int64_t q = 0, r = 0, dq = 0, dr = 0, d = 1;
  void init(std::int64_t n, std::int64_t delta, std::int64_t divisor) {
    d = divisor;
    q = floor_div(n, d), r = n - q * d;
    dq = floor_div(delta, d), dr = delta - dq * d;
  }
  void step() {
    q += dq, r += dr;
    if (r >= d) ++q, r -= d;
  }
};

// One edge a->b of a triangle with positive area: E(p) = A (px - xa) + B (py - ya) is > 0 inside.
struct Edge {
  std::int64_t a = 0, b = 0;   // A = ya - yb, B = xb - xa (1/256 px units)
  std::int64_t min_value = 0;  // top-left rule: centres on the edge (E == 0) count only for top/left edges
};

// y down, interior on the side E > 0: a "left" edge runs upward (dy < 0); a "top" edge is horizontal and
// runs right (dy == 0, dx > 0), with the interior below it.
template <typename T>
bool is_top_left(const T& dx, const T& dy) {
  return dy < T(0) || (dy == T(0) && dx > T(0));
}

Edge make_edge(const ScreenVertex& from, const ScreenVertex& to) {
  Edge e;
  e.a = std::int64_t{from.y} - to.y;
  e.b = std::int64_t{to.x} - from.x;
  e.min_value = is_top_left<std::int64_t>(e.b, -e.a) ? 0 : 1;
  return e;
}

// Coverage of one fast-path triangle: calls span(j, lo, hi, w, step, row_step, area) for every row j with
// covered pixels [lo, hi] inside `clip`. w[k] is vertex k's barycentric weight at pixel lo times the
// doubled area (vertex order as given, whatever the winding), step[k] its change per pixel to the right,
// row_step[k] per row down.
// Returns the doubled area (0: degenerate, nothing covered).
template <typename Span>
std::int64_t for_each_span(const std::int32_t (&xs)[3], const std::int32_t (&ys)[3], Rect clip,
                           SamplePoint sample, StopMeter& meter, Span&& span) {
  ScreenVertex v[3];
  for (int k = 0; k < 3; ++k) v[k].x = xs[k], v[k].y = ys[k];
  std::int64_t area = (std::int64_t{v[1].x} - v[0].x) * (std::int64_t{v[2].y} - v[0].y) -
                      (std::int64_t{v[1].y} - v[0].y) * (std::int64_t{v[2].x} - v[0].x);
  if (area == 0) return 0;  // degenerate: covers nothing
  const bool swapped = area < 0;
  if (swapped) {  // both windings are drawn: normalize to positive area
    std::swap(v[1], v[2]);
    area = -area;
  }

  // Pixels whose sample point (256 i + sample.x, 256 j + sample.y) lies in the bounding box, clamped to
  // the clip rectangle.
  const std::int64_t min_x = std::min({v[0].x, v[1].x, v[2].x}), max_x = std::max({v[0].x, v[1].x, v[2].x});
  const std::int64_t min_y = std::min({v[0].y, v[1].y, v[2].y}), max_y = std::max({v[0].y, v[1].y, v[2].y});
  const std::int64_t i_lo = std::max<std::int64_t>(clip.x0, ceil_div(min_x - sample.x, kSubpixelScale));
  const std::int64_t i_hi = std::min<std::int64_t>(clip.x1 - 1, floor_div(max_x - sample.x, kSubpixelScale));
  const std::int64_t j_lo = std::max<std::int64_t>(clip.y0, ceil_div(min_y - sample.y, kSubpixelScale));
  const std::int64_t j_hi = std::min<std::int64_t>(clip.y1 - 1, floor_div(max_y - sample.y, kSubpixelScale));
  if (i_lo > i_hi || j_lo > j_hi) return area;

  // Edge k is opposite normalized vertex k, so its value is that vertex's weight times `area`; reordered
  // to the given vertex order once here, so the per-row work indexes directly.
  Edge e[3] = {make_edge(v[1], v[2]), make_edge(v[2], v[0]), make_edge(v[0], v[1])};
  const ScreenVertex* origin[3] = {&v[1], &v[2], &v[0]};
  if (swapped) {
    std::swap(e[1], e[2]);
    std::swap(origin[1], origin[2]);
  }
  const std::int64_t px = i_lo * kSubpixelScale + sample.x;
  std::int64_t row_value[3], step[3], row_step[3];
  for (int k = 0; k < 3; ++k) {
    row_value[k] = e[k].a * (px - origin[k]->x) + e[k].b * (j_lo * kSubpixelScale + sample.y - origin[k]->y);
    step[k] = e[k].a * kSubpixelScale;
    row_step[k] = e[k].b * kSubpixelScale;
  }

  // The covered span of each row, solved exactly per edge instead of testing every pixel of the box:
  // E(i) = E(i_lo) + A * 256 * (i - i_lo) >= min_value gives, for A > 0, i >= i_lo + ceil((min - E) / s)
  // = i_lo - floor((E - min) / s), and for A < 0, i <= i_lo + floor((E - min) / -s). E - min changes by
  // B * 256 per row, so each bound steps without a division.
  FloorStepper bound[3];
  for (int k = 0; k < 3; ++k) {
    const std::int64_t s = e[k].a * kSubpixelScale;
    if (s != 0) bound[k].init(row_value[k] - e[k].min_value, e[k].b * kSubpixelScale, s > 0 ? s : -s);
  }
  for (std::int64_t j = j_lo; j <= j_hi; ++j) {
    std::int64_t lo = i_lo, hi = i_hi;
    for (int k = 0; k < 3; ++k) {
      if (e[k].a > 0)
        lo = std::max(lo, i_lo - bound[k].q);
      else if (e[k].a < 0)
        hi = std::min(hi, i_lo + bound[k].q);
      else if (row_value[k] < e[k].min_value)
        lo = hi + 1;
      bound[k].step();
    }
    if (lo <= hi) {
      std::int64_t w[3];
      for (int k = 0; k < 3; ++k) w[k] = row_value[k] + step[k] * (lo - i_lo);
      span(j, lo, hi, w, step, row_step, area);
    }
    for (int k = 0; k < 3; ++k) row_value[k] += e[k].b * kSubpixelScale;
    // deadline: a triangle as large as the image is checked every few dozen rows
    if (meter.add(StopMeter::kRowWork + std::max<std::int64_t>(0, hi - lo + 1))) break;
  }
  return area;
}

// Colour is affine along a row: each channel starts at the exact barycentric value of the span's first
// pixel (from the exact integer weights, so it does not depend on which band draws the row) and steps by
// a constant 16.16 slope. Over the longest span (16384 px) the stepping error stays below 0.13 of a level,
// and clamping to the vertex range keeps the result inside it. Equal vertex colours give a slope of
// exactly 0 (the edge steps sum to 0), so flat and smooth agree exactly.
inline std::int64_t round_to_int(double x) {
  return static_cast<std::int64_t>(x >= 0 ? x + 0.5 : x - 0.5);
}

// The channels (0 r, 1 g, 2 b, 3 a) a format of C channels stores: grey r, grey+alpha r and a, RGB, RGBA.
template <int C>
constexpr int kStoredCount = C == 2 ? 2 : C;
template <int C>
constexpr std::array<int, 4> kStored = C == 1   ? std::array<int, 4>{0}
                                       : C == 2 ? std::array<int, 4>{0, 3}
                                       : C == 3 ? std::array<int, 4>{0, 1, 2}
                                                : std::array<int, 4>{0, 1, 2, 3};

// An affine channel takes its extremes at the ends of a span: when both ends round inside the vertex
// range, every pixel between does, and the per-pixel clamp can go. Only the channels format C stores
// are checked.
template <int C>
bool affine_span_in_range(const std::int64_t (&value)[4], const std::int64_t (&slope)[4], std::int64_t count,
                          const std::uint8_t (&lo)[4], const std::uint8_t (&hi)[4]) {
  for (int k = 0; k < kStoredCount<C>; ++k) {
    const int ch = kStored<C>[k];
    // A slope of 2^24 or more (a sliver's) leaves the range within one pixel; checking it first also keeps
    // the product below from overflowing.
    if (count > 1 && (slope[ch] >= std::int64_t{1} << 24 || slope[ch] <= -(std::int64_t{1} << 24)))
      return false;
    const std::int64_t first = value[ch], last = value[ch] + slope[ch] * (count - 1);
    if (std::min(first, last) < std::int64_t{lo[ch]} << 16 || std::max(first, last) >= (hi[ch] + 1) << 16)
      return false;
  }
  return true;
}

// The smooth opaque span without clamps. RGB and RGBA go four pixels per step (GCC vector extensions:
// SSE2 on x86-64), each lane packing one pixel's bytes into a word; RGB stores 4 bytes per 3-byte pixel,
// the spare byte rewritten by the next pixel, so the span's last pixel always goes to the scalar loop and
// nothing past the span is written. 32-bit lanes hold the 16.16 values: in a span of two or more pixels
// whose ends are in range, each stored channel stays below 2^24 and its slope below 2^24 per pixel
// (affine_span_in_range). A one-pixel span's slope is unbounded, so the scalar loop steps in 64 bits.
template <int C>
void store_affine_span(std::uint8_t* p, std::int64_t count, const std::int64_t (&value)[4],
                       const std::int64_t (&slope)[4]) {
  std::int64_t n = 0;
  if constexpr (C >= 3) {
    if (count >= 5) {
      using Lanes = std::int32_t __attribute__((vector_size(16)));
      using Words = std::uint32_t __attribute__((vector_size(16)));
      const Lanes lane = {0, 1, 2, 3};
      auto lanes = [&](int ch) {
        return static_cast<std::int32_t>(value[ch]) + static_cast<std::int32_t>(slope[ch]) * lane;
      };
      auto step = [&](int ch) { return static_cast<std::int32_t>(4 * slope[ch]); };
      Lanes vr = lanes(0), vg = lanes(1), vb = lanes(2);
      const std::int32_t sr = step(0), sg = step(1), sb = step(2);
      [[maybe_unused]] Lanes va;
      [[maybe_unused]] std::int32_t sa = 0;
      if constexpr (C == 4) va = lanes(3), sa = step(3);
      const std::int64_t blocks_end = C == 3 ? count - 1 : count;
      for (; n + 4 <= blocks_end; n += 4, p += 4 * C) {
        Words word = reinterpret_cast<Words>(vr >> 16) | reinterpret_cast<Words>(vg >> 16) << 8 |
                     reinterpret_cast<Words>(vb >> 16) << 16;
        if constexpr (C == 4) {
          word |= reinterpret_cast<Words>(va >> 16) << 24;
          va += sa;
          std::memcpy(p, &word, 16);
        } else {
          for (int k = 0; k < 4; ++k) {
            const std::uint32_t w = word[k];
            std::memcpy(p + 3 * k, &w, 4);
          }
        }
        vr += sr, vg += sg, vb += sb;
      }
    }
  }
  // Only the stored channels are advanced: the others' slopes are not bounded by any check.
  std::int64_t r = value[0] + slope[0] * n, g = 0, b = 0, a = 0;
  if constexpr (C >= 3) g = value[1] + slope[1] * n, b = value[2] + slope[2] * n;
  if constexpr (C == 2 || C == 4) a = value[3] + slope[3] * n;
  for (std::uint8_t* const end = p + (count - n) * C; p != end; p += C) {
    p[0] = static_cast<std::uint8_t>(r >> 16), r += slope[0];
    if constexpr (C == 2) p[1] = static_cast<std::uint8_t>(a >> 16), a += slope[3];
    if constexpr (C >= 3) {
      p[1] = static_cast<std::uint8_t>(g >> 16), g += slope[1];
      p[2] = static_cast<std::uint8_t>(b >> 16), b += slope[2];
    }
    if constexpr (C == 4) p[3] = static_cast<std::uint8_t>(a >> 16), a += slope[3];
  }
}

template <int C>
void fill_triangle(const ScreenTriangle& tri, PrimitivePlan mode, Image& image, Rect clip, SamplePoint sample,
                   StopMeter& meter) {
  const std::int32_t xs[3] = {tri.v[0].x, tri.v[1].x, tri.v[2].x},
                     ys[3] = {tri.v[0].y, tri.v[1].y, tri.v[2].y};
  const Rgba8 c[3] = {tri.v[0].color, tri.v[1].color, tri.v[2].color};
  if (!mode.smooth) {
    for_each_span(xs, ys, clip, sample, meter,
                  [&](std::int64_t j, std::int64_t lo, std::int64_t hi, const std::int64_t(&)[3],
                      const std::int64_t(&)[3], const std::int64_t(&)[3], std::int64_t) {
                    shade_span<C>(image.pixels.data() + (j * image.width + lo) * C, hi - lo + 1, mode, c[0],
                                  [&] { return c[0]; });
                  });
    return;
  }
  const std::uint8_t channels[4][3] = {
      {c[0].r, c[1].r, c[2].r}, {c[0].g, c[1].g, c[2].g}, {c[0].b, c[1].b, c[2].b}, {c[0].a, c[1].a, c[2].a}};
  std::int64_t slope[4] = {};  // 16.16 per pixel
  std::uint8_t lo_c[4], hi_c[4];
  double scale = 0;
  for_each_span(
      xs, ys, clip, sample, meter,
      [&](std::int64_t j, std::int64_t lo, std::int64_t hi, const std::int64_t(&w)[3],
          const std::int64_t(&step)[3], const std::int64_t(&)[3], std::int64_t area) {
        if (scale == 0) {  // once per triangle: depends on the triangle only
          scale = 65536.0 / static_cast<double>(area);
          for (int ch = 0; ch < 4; ++ch) {
            const std::uint8_t* v = channels[ch];
            slope[ch] =
                round_to_int(static_cast<double>(step[0] * v[0] + step[1] * v[1] + step[2] * v[2]) * scale);
            lo_c[ch] = std::min({v[0], v[1], v[2]});
            hi_c[ch] = std::max({v[0], v[1], v[2]});
          }
        }
        // 16.16, with a half added for rounding; exact numerator < 2^58, so the double is exact to 2^-29
        // levels. Only the channels the format stores, and alpha when it weighs a blend.
        std::int64_t value[4] = {};
        auto start = [&](int ch) {
          const std::uint8_t* v = channels[ch];
          value[ch] =
              round_to_int(static_cast<double>(w[0] * v[0] + w[1] * v[1] + w[2] * v[2]) * scale) + 0x8000;
        };
        for (int k = 0; k < kStoredCount<C>; ++k) start(kStored<C>[k]);
        if ((C == 1 || C == 3) && mode.blend) start(3);
        std::uint8_t* const p = image.pixels.data() + (j * image.width + lo) * C;
        const std::int64_t count = hi - lo + 1;
        if (!mode.blend && affine_span_in_range<C>(value, slope, count, lo_c, hi_c)) {
          store_affine_span<C>(p, count, value, slope);
          return;
        }
        shade_span<C>(p, count, mode, c[0], [&] {
          std::uint8_t out[4];
          for (int ch = 0; ch < 4; ++ch) {
            out[ch] =
                static_cast<std::uint8_t>(std::clamp<std::int64_t>(value[ch] >> 16, lo_c[ch], hi_c[ch]));
            value[ch] += slope[ch];
          }
          return Rgba8{out[0], out[1], out[2], out[3]};
        });
      });
}

// ---- Triangles with depth (3D): the same coverage, then depth test and perspective-correct shading ----

template <int C>
void fill_depth_triangle(const DepthTriangle& tri, const DrawOp& op, const DrawList& list, Image& image,
                         float* depth, Rect clip, SamplePoint sample, StopMeter& meter) {
  const std::int32_t xs[3] = {tri.v[0].x, tri.v[1].x, tri.v[2].x},
                     ys[3] = {tri.v[0].y, tri.v[1].y, tri.v[2].y};
  const DepthVertex* v = tri.v;
  const PrimitivePlan mode = op.mode;
  const Rgba8 flat{to_byte(v[0].color[0]), to_byte(v[0].color[1]), to_byte(v[0].color[2]),
                   to_byte(v[0].color[3])};
  const double flip = tri.back_facing ? -1.0 : 1.0;  // two-sided lighting
  for_each_span(
      xs, ys, clip, sample, meter,
      [&](std::int64_t j, std::int64_t lo, std::int64_t hi, const std::int64_t(&w)[3],
          const std::int64_t(&step)[3], const std::int64_t(&)[3], std::int64_t area) {
        const double inv_area = 1.0 / static_cast<double>(area);
        const std::size_t row = static_cast<std::size_t>(j) * image.width;
        for (std::int64_t i = lo; i <= hi; ++i) {
          const std::int64_t n = i - lo;
          // screen-space barycentrics; depth (z / w) is affine in screen space
          const double l[3] = {static_cast<double>(w[0] + step[0] * n) * inv_area,
                               static_cast<double>(w[1] + step[1] * n) * inv_area,
                               static_cast<double>(w[2] + step[2] * n) * inv_area};
          const float z = static_cast<float>(l[0] * v[0].depth + l[1] * v[1].depth + l[2] * v[2].depth);
          float& stored = depth[row + i];
          if (!(z > stored)) continue;  // reversed depth: larger is nearer; ties keep what was drawn first
          stored = z;
          std::uint8_t* p = image.pixels.data() + (row + i) * C;
          if (!mode.smooth) {
            if (mode.blend)
              blend<C>(p, flat);
            else
              store<C>(p, flat);
            continue;
          }
          // perspective-correct weights: interpolate attribute / w and 1 / w, then divide
          double q[3], sum = 0;
          for (int k = 0; k < 3; ++k) sum += q[k] = l[k] * v[k].inv_w;
          for (double& qk : q) qk /= sum;
          double rgba[4];
          for (int c = 0; c < 4; ++c)
            rgba[c] = q[0] * v[0].color[c] + q[1] * v[1].color[c] + q[2] * v[2].color[c];
          if (op.mode.light_per_pixel) {
            double nrm[3];
            for (int c = 0; c < 3; ++c)
              nrm[c] = q[0] * v[0].normal[c] + q[1] * v[1].normal[c] + q[2] * v[2].normal[c];
            const double len = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
            const double lambert = len > 0 ? flip *
                                                 (nrm[0] * list.to_light[0] + nrm[1] * list.to_light[1] +
                                                  nrm[2] * list.to_light[2]) /
                                                 len
                                           : 0;
            const double shade = list.ambient + (1 - list.ambient) * std::max(0.0, lambert);
            for (int c = 0; c < 3; ++c) rgba[c] *= shade;
          }
          const Rgba8 c{to_byte(rgba[0]), to_byte(rgba[1]), to_byte(rgba[2]), to_byte(rgba[3])};
          if (mode.blend)
            blend<C>(p, c);
          else
            store<C>(p, c);
        }
      });
}

// ---- Triangles, exact wide path: vertices beyond the fast range, up to 2^128 px --------------------------

template <int C>
void fill_huge_triangle(const HugeTriangle& tri, PrimitivePlan mode, Image& image, Rect clip,
                        SamplePoint sample, StopMeter& meter) {
  int order[3] = {0, 1, 2};
  Wide x[3], y[3];
  for (int k = 0; k < 3; ++k) x[k] = Wide::from_double(tri.x[k]), y[k] = Wide::from_double(tri.y[k]);
  Wide area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  if (area == Wide(0)) return;
  if (area.negative()) {
    std::swap(x[1], x[2]), std::swap(y[1], y[2]), std::swap(order[1], order[2]);
    area = -area;
  }
  // Bounding box in doubles (exact integral values), widened by a pixel: it only bounds the work, the
  // per-row spans below decide coverage exactly.
  auto pixel_range = [](double lo_units, double hi_units, int c0, int c1) {
    // widened by one pixel on each side, so the sample's offset within the pixel does not matter here
    const double lo = std::ceil(lo_units / kSubpixelScale) - 2,
                 hi = std::floor(hi_units / kSubpixelScale) + 1;
    return std::pair<std::int64_t, std::int64_t>{static_cast<std::int64_t>(std::max<double>(c0, lo)),
                                                 static_cast<std::int64_t>(std::min<double>(c1 - 1, hi))};
  };
  const auto [i_lo, i_hi] = pixel_range(std::min({tri.x[0], tri.x[1], tri.x[2]}),
                                        std::max({tri.x[0], tri.x[1], tri.x[2]}), clip.x0, clip.x1);
  const auto [j_lo, j_hi] = pixel_range(std::min({tri.y[0], tri.y[1], tri.y[2]}),
                                        std::max({tri.y[0], tri.y[1], tri.y[2]}), clip.y0, clip.y1);
  if (i_lo > i_hi || j_lo > j_hi) return;

  Wide a[3], row_value[3], step_x[3], step_y[3], min_value[3];
  const Wide px(i_lo * kSubpixelScale + sample.x), py(j_lo * kSubpixelScale + sample.y);
  for (int k = 0; k < 3; ++k) {
    const int from = (k + 1) % 3, to = (k + 2) % 3;  // edge opposite vertex k
    a[k] = y[from] - y[to];
    const Wide b = x[to] - x[from];
    min_value[k] = is_top_left(b, -a[k]) ? Wide(0) : Wide(1);
    row_value[k] = a[k] * (px - x[from]) + b * (py - y[from]);
    step_x[k] = a[k] * Wide(kSubpixelScale);
    step_y[k] = b * Wide(kSubpixelScale);
  }
  // Colour is affine across the triangle: weights in double suffice for 8-bit output; the result is
  // clamped to the vertex range, which the exact value never leaves.
  Rgba8 col[3];
  for (int k = 0; k < 3; ++k) col[k] = tri.color[order[k]];
  const double area_d = area.to_double();
  const std::int64_t width = i_hi - i_lo + 1;

  for (std::int64_t j = j_lo; j <= j_hi; ++j) {
    std::int64_t lo = 0, hi = width - 1;  // offsets from i_lo
    for (int k = 0; k < 3; ++k) {
      const Wide slack = row_value[k] - min_value[k];  // E(i_lo) - min; need slack + step * n >= 0
      if (step_x[k] > Wide(0))
        lo = std::max(lo, -floor_div_clamped(slack, step_x[k], -(width + 1), 0));
      else if (step_x[k] < Wide(0))
        hi = std::min(hi, floor_div_clamped(slack, -step_x[k], -1, width));
      else if (slack.negative())
        lo = hi + 1;
    }
    if (lo <= hi) {
      double w[3], dw[3];
      for (int k = 0; k < 3; ++k) {
        w[k] = (row_value[k] + step_x[k] * Wide(lo)).to_double() / area_d;
        dw[k] = step_x[k].to_double() / area_d;
      }
      std::uint8_t* p = image.pixels.data() + (j * image.width + i_lo + lo) * C;
      shade_span<C>(p, hi - lo + 1, mode, col[0], [&] {
        auto channel = [&](std::uint8_t Rgba8::*m) {
          const double v = w[0] * (col[0].*m) + w[1] * (col[1].*m) + w[2] * (col[2].*m);
          const double lo_c = std::min({col[0].*m, col[1].*m, col[2].*m}),
                       hi_c = std::max({col[0].*m, col[1].*m, col[2].*m});
          return to_byte(std::clamp(v, lo_c, hi_c));
        };
        const Rgba8 c{channel(&Rgba8::r), channel(&Rgba8::g), channel(&Rgba8::b), channel(&Rgba8::a)};
        w[0] += dw[0], w[1] += dw[1], w[2] += dw[2];
        return c;
      });
    }
    for (int k = 0; k < 3; ++k) row_value[k] += step_y[k];
    if (meter.add(StopMeter::kRowWork + std::max<std::int64_t>(0, hi - lo + 1))) return;  // deadline
  }
}

// ---- Lines: symmetric Bresenham, clipped before stepping ------------------------------------------------

// T is __int128 for endpoints within 2^60 px (every product below fits), Wide beyond.
template <int C, typename T>
void draw_line(const ScreenLine& line, PrimitivePlan mode, Image& image, float* depth, Rect clip) {
  auto to_t = [](double v) {
    if constexpr (std::is_same_v<T, Wide>)
      return Wide::from_double(v);
    else
      return static_cast<T>(v);
  };
  T x0 = to_t(line.x0), y0 = to_t(line.y0), x1 = to_t(line.x1), y1 = to_t(line.y1);
  Rgba8 c0 = line.c0, c1 = line.c1;
  float z0 = line.depth0, z1 = line.depth1;
  bool draw_first = line.draw_first, draw_last = line.draw_last;
  // Canonical order, decided exactly: along the major axis (x when |dx| >= |dy|) the first endpoint has
  // the smaller coordinate. a->b and b->a become the same line, hence the same pixels.
  auto abs_t = [](const T& v) { return v < T(0) ? -v : v; };
  const bool x_major = !(abs_t(x1 - x0) < abs_t(y1 - y0));
  if (!x_major) std::swap(x0, y0), std::swap(x1, y1);  // from here on: u = x0/x1 axis, v = y0/y1 axis
  if (x1 < x0 || (x1 == x0 && y1 < y0)) {
    std::swap(x0, x1), std::swap(y0, y1), std::swap(c0, c1), std::swap(draw_first, draw_last);
    std::swap(z0, z1);
  }
  const T &u0 = x0, &u1 = x1, &v0 = y0, &v1 = y1;
  const T du = u1 - u0, dv = v1 - v0;  // du >= |dv| >= 0
  const std::int64_t u_min = x_major ? clip.x0 : clip.y0, u_max = (x_major ? clip.x1 : clip.y1) - 1;
  const std::int64_t v_min = x_major ? clip.y0 : clip.x0, v_max = (x_major ? clip.y1 : clip.x1) - 1;

  // Visible columns: [u0, u1] minus the joint pixels owned by neighbouring segments, within the clip.
  auto to_i64 = [](const T& v) -> std::int64_t {
    if constexpr (std::is_same_v<T, Wide>)
      return v.low64();
    else
      return static_cast<std::int64_t>(v);
  };
  const T first = draw_first ? u0 : u0 + T(1), last = draw_last ? u1 : u1 - T(1);
  if (last < T(u_min) || T(u_max) < first || last < first) return;
  std::int64_t lo = first < T(u_min) ? u_min : to_i64(first);
  std::int64_t hi = T(u_max) < last ? u_max : to_i64(last);

  // Pixel index steps along the major and minor axes (colour bytes are C per pixel, depth one float).
  const std::size_t stride_u = x_major ? 1 : static_cast<std::size_t>(image.width);
  const std::size_t stride_v = x_major ? static_cast<std::size_t>(image.width) : 1;
  // Writes one pixel; 3D lines first pass the depth test (reversed: larger is nearer).
  auto plot = [&](std::int64_t u, std::int64_t v, float z, auto&& color) {
    const std::size_t index = static_cast<std::size_t>(u) * stride_u + static_cast<std::size_t>(v) * stride_v;
    if (mode.depth) {
      if (!(z > depth[index])) return;
      depth[index] = z;
    }
    shade_span<C>(image.pixels.data() + index * C, 1, mode, c0, color);
  };

  if (du == T(0)) {  // both endpoints in one pixel
    if (!(v0 < T(v_min)) && !(T(v_max) < v0)) plot(lo, to_i64(v0), std::max(z0, z1), [&] { return c0; });
    return;
  }

  // The Bresenham row of column u is the one nearest the exact line through the two pixel centres, ties
  // toward larger v: v(u) = floor(N(u) / 2du) with N(u) = 2 (u - u0) dv + du + 2 du v0. Rows outside the
  // clip are reported as v_min - 1 or v_max + 1: only whether they are inside matters there.
  const T two_du = du + du, two_dv = dv + dv;
  const T base = du + two_du * v0;
  auto numerator = [&](std::int64_t u) { return two_dv * (T(u) - u0) + base; };
  auto v_at = [&](std::int64_t u) { return floor_div_clamped(numerator(u), two_du, v_min - 1, v_max + 1); };

  // v(u) is monotone, so the columns whose row is inside the clip form one interval: find its ends by
  // bisection. The cost is then the visible length, however far the endpoints lie outside.
  const bool rising = !(dv < T(0));
  {  // first column that has reached the clip rows
    std::int64_t a = lo, b = hi + 1;
    while (a < b) {
      const std::int64_t m = a + (b - a) / 2;
      const std::int64_t v = v_at(m);
      if (rising ? v < v_min : v > v_max)
        a = m + 1;
      else
        b = m;
    }
    lo = a;
  }
  auto inside = [&](std::int64_t u) {
    const std::int64_t v = v_at(u);
    return v >= v_min && v <= v_max;
  };
  if (lo > hi || !inside(lo)) return;
  {  // last column still inside the clip rows
    std::int64_t a = lo, b = hi;
    while (a < b) {
      const std::int64_t m = a + (b - a + 1) / 2;
      if (inside(m))
        a = m;
      else
        b = m - 1;
    }
    hi = a;
  }

  // Incremental Bresenham from lo: row v and remainder r = N(u) - 2du v in [0, 2du).
  std::int64_t v = v_at(lo);
  T r = numerator(lo) - two_du * T(v);
  auto lerp_t = [&](std::int64_t u) {  // (u - u0) / du as a double, for depth only
    if constexpr (std::is_same_v<T, Wide>)
      return (T(u) - u0).to_double() / du.to_double();
    else
      return static_cast<double>(T(u) - u0) / static_cast<double>(du);
  };
  auto lerp = [&](std::uint8_t a, std::uint8_t b, const T& t) {  // a + round((b - a) t / du), exact
    return static_cast<std::uint8_t>(a +
                                     floor_div_clamped(T(2 * (int{b} - int{a})) * t + du, two_du, -255, 255));
  };
  for (std::int64_t u = lo; u <= hi; ++u) {
    // 3D lines: z / w is affine along the screen-space line
    const float z = mode.depth ? static_cast<float>(z0 + (z1 - z0) * lerp_t(u)) : 0.0f;
    plot(u, v, z, [&] {
      const T t = T(u) - u0;
      return Rgba8{lerp(c0.r, c1.r, t), lerp(c0.g, c1.g, t), lerp(c0.b, c1.b, t), lerp(c0.a, c1.a, t)};
    });
    r += two_dv;  // step the minor axis when the remainder leaves [0, 2du)
    if (!(r < two_du))
      r -= two_du, ++v;
    else if (r < T(0))
      r += two_du, --v;
  }
}

bool line_fits_int128(const ScreenLine& l) {
  constexpr double kLimit = 0x1p60;  // keeps 2 dv (u - u0) + 2 du v0 below 2^125
  return std::fabs(l.x0) <= kLimit && std::fabs(l.y0) <= kLimit && std::fabs(l.x1) <= kLimit &&
         std::fabs(l.y1) <= kLimit;
}

// A 1-px line steps one pixel per column (or row) of its longer axis, clipped to the band first.
std::int64_t line_work(const ScreenLine& l, Rect clip) {
  const double steps = std::max(std::fabs(l.x1 - l.x0), std::fabs(l.y1 - l.y0));  // pixels
  const double most = std::max(clip.x1 - clip.x0, clip.y1 - clip.y0);
  return 1 + static_cast<std::int64_t>(std::min(steps, most));
}

template <int C>
void draw_all(const DrawList& list, Image& image, float* depth, Rect clip, StopMeter& meter,
              SamplePoint sample) {
  for (const DrawOp& op : list.ops) {
    for (std::uint32_t k = op.first; k < op.first + op.count; ++k) {
      if (meter.add(StopMeter::kPrimitiveWork)) return;
      switch (op.kind) {
        case DrawOp::Kind::triangles:
          fill_triangle<C>(list.triangles[k], op.mode, image, clip, sample, meter);
          break;
        case DrawOp::Kind::huge_triangles:
          fill_huge_triangle<C>(list.huge_triangles[k], op.mode, image, clip, sample, meter);
          break;
        case DrawOp::Kind::depth_triangles:
          fill_depth_triangle<C>(list.depth_triangles[k], op, list, image, depth, clip, sample, meter);
          break;
        case DrawOp::Kind::lines:  // clipped to the image, so at most one pixel per column or row of it
          if (line_fits_int128(list.lines[k]))
            draw_line<C, __int128>(list.lines[k], op.mode, image, depth, clip);
          else
            draw_line<C, Wide>(list.lines[k], op.mode, image, depth, clip);
          meter.add(line_work(list.lines[k], clip));
          break;
      }
    }
  }
}

}  // namespace

void draw(const DrawList& list, Image& image, float* depth, Rect clip, StopMeter& meter, SamplePoint sample) {
  switch (image.format) {
    case PixelFormat::grey8:
      return draw_all<1>(list, image, depth, clip, meter, sample);
    case PixelFormat::grey_alpha8:
      return draw_all<2>(list, image, depth, clip, meter, sample);
    case PixelFormat::rgb8:
      return draw_all<3>(list, image, depth, clip, meter, sample);
    case PixelFormat::rgba8:
      return draw_all<4>(list, image, depth, clip, meter, sample);
  }
}

const std::vector<SamplePoint>& sample_pattern(int samples) {
  // Direct3D's standard multisample positions, in 1/16 px from the pixel centre, scaled to 1/256 px from
  // the pixel's corner: every position is on the rasterizer's sub-pixel grid.
  auto pattern = [](std::initializer_list<std::pair<int, int>> sixteenths) {
    std::vector<SamplePoint> out;
    for (auto [x, y] : sixteenths) out.push_back({128 + 16 * x, 128 + 16 * y});
    return out;
  };
  static const std::vector<SamplePoint> one{{128, 128}};
  static const std::vector<SamplePoint> four = pattern({{-2, -6}, {6, -2}, {-6, 2}, {2, 6}});
  static const std::vector<SamplePoint> eight =
      pattern({{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}});
  static const std::vector<SamplePoint> sixteen = pattern({{1, 1},
                                                           {-1, -3},
                                                           {-3, 2},
                                                           {4, -1},
                                                           {-5, -2},
                                                           {2, 5},
                                                           {5, 3},
                                                           {3, -5},
                                                           {-2, 6},
                                                           {0, -7},
                                                           {-4, -6},
                                                           {-6, 4},
                                                           {-8, 0},
                                                           {7, -4},
                                                           {6, 7},
                                                           {-7, -8}});
  switch (samples) {
    case 4:
      return four;
    case 8:
      return eight;
    case 16:
      return sixteen;
    default:
      return one;
  }
}

}  // namespace raster::detail
