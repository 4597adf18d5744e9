#include "raster.h"

#include <algorithm>
#include <cstdlib>
#include <utility>

#include "shade.h"

namespace raster::detail {
namespace {

// Integer division rounding toward -infinity / +infinity (C++ '/' rounds toward zero). d > 0.
template <typename T>
T floor_div(T n, T d) {
  T q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}
template <typename T>
T ceil_div(T n, T d) {
  T q = n / d;
  return (n % d != 0 && n > 0) ? q + 1 : q;
}

constexpr std::int64_t kHalfPixel = kSubpixelScale / 2;

// One edge a->b of a triangle with positive area: E(p) = A (px - xa) + B (py - ya) is > 0 inside.
struct Edge {
  std::int64_t a = 0, b = 0;  // A = ya - yb, B = xb - xa (1/256 px units)
  std::int64_t min_value = 0; // top-left rule: on-edge centres (E == 0) count only for top and left edges
  std::int64_t at(std::int64_t px, std::int64_t py, const ScreenVertex& o) const {
    return a * (px - o.x) + b * (py - o.y);
  }
};

Edge make_edge(const ScreenVertex& from, const ScreenVertex& to) {
  Edge e;
  e.a = std::int64_t{from.y} - to.y;
  e.b = std::int64_t{to.x} - from.x;
  const std::int64_t dy = std::int64_t{to.y} - from.y;
  // y down, interior on the side E > 0: a "left" edge runs upward (dy < 0), a "top" edge is horizontal
  // running right (dy == 0, dx > 0) with the interior below it.
  const bool top_left = dy < 0 || (dy == 0 && e.b > 0);
  e.min_value = top_left ? 0 : 1;
  return e;
}

template <int C>
void fill_triangle(const ScreenTriangle& tri, PrimitivePlan mode, Image& image, Rect clip) {
  ScreenVertex v0 = tri.v[0], v1 = tri.v[1], v2 = tri.v[2];
  std::int64_t area = (std::int64_t{v1.x} - v0.x) * (std::int64_t{v2.y} - v0.y) -
                      (std::int64_t{v1.y} - v0.y) * (std::int64_t{v2.x} - v0.x);
  if (area == 0) return;  // degenerate: covers nothing
  if (area < 0) {         // both windings are drawn: normalize to positive area
    std::swap(v1, v2);
    area = -area;
  }

  // Pixels whose centre (256 i + 128) lies in the bounding box, clamped to the clip rectangle.
  const std::int64_t min_x = std::min({v0.x, v1.x, v2.x}), max_x = std::max({v0.x, v1.x, v2.x});
  const std::int64_t min_y = std::min({v0.y, v1.y, v2.y}), max_y = std::max({v0.y, v1.y, v2.y});
  const std::int64_t i_lo = std::max<std::int64_t>(clip.x0, ceil_div(min_x - kHalfPixel, kSubpixelScale));
  const std::int64_t i_hi = std::min<std::int64_t>(clip.x1 - 1, floor_div(max_x - kHalfPixel, kSubpixelScale));
  const std::int64_t j_lo = std::max<std::int64_t>(clip.y0, ceil_div(min_y - kHalfPixel, kSubpixelScale));
  const std::int64_t j_hi = std::min<std::int64_t>(clip.y1 - 1, floor_div(max_y - kHalfPixel, kSubpixelScale));
  if (i_lo > i_hi || j_lo > j_hi) return;

  // Edge k is opposite vertex k, so its value is vertex k's barycentric weight times `area`.
  const Edge e[3] = {make_edge(v1, v2), make_edge(v2, v0), make_edge(v0, v1)};
  const ScreenVertex* origin[3] = {&v1, &v2, &v0};
  const Rgba8 flat = v0.color;
  const int stride = image.width * C;

  for (std::int64_t j = j_lo; j <= j_hi; ++j) {
    const std::int64_t py = j * kSubpixelScale + kHalfPixel;
    const std::int64_t px = i_lo * kSubpixelScale + kHalfPixel;
    // The covered span of this row, solved exactly per edge instead of testing every pixel of the box:
    // E(i) = E(i_lo) + A * 256 * (i - i_lo) >= min_value.
    std::int64_t lo = i_lo, hi = i_hi;
    std::int64_t value[3];
    for (int k = 0; k < 3; ++k) {
      value[k] = e[k].at(px, py, *origin[k]);
      const std::int64_t step = e[k].a * kSubpixelScale;
      if (step > 0) {
        lo = std::max(lo, i_lo + ceil_div(e[k].min_value - value[k], step));
      } else if (step < 0) {
        hi = std::min(hi, i_lo + floor_div(value[k] - e[k].min_value, -step));
      } else if (value[k] < e[k].min_value) {
        lo = hi + 1;
      }
    }
    if (lo > hi) continue;
    std::uint8_t* p = image.pixels.data() + j * stride + lo * C;
    std::uint8_t* const end = p + (hi - lo + 1) * C;
    if (!mode.smooth) {
      if (mode.blend) {
        for (; p != end; p += C) blend<C>(p, flat);
      } else {
        for (; p != end; p += C) store<C>(p, flat);
      }
      continue;
    }
    std::int64_t w[3], step[3];
    for (int k = 0; k < 3; ++k) {
      step[k] = e[k].a * kSubpixelScale;
      w[k] = value[k] + step[k] * (lo - i_lo);
    }
    for (; p != end; p += C) {
      const Rgba8 c = mix3(w[0], w[1], w[2], area, v0.color, v1.color, v2.color);
      if (mode.blend) blend<C>(p, c);
      else store<C>(p, c);
      w[0] += step[0], w[1] += step[1], w[2] += step[2];
    }
  }
}

// Interpolates one channel along a line: c0 + round((c1 - c0) * t / n) in integers.
std::uint8_t lerp_channel(std::uint8_t c0, std::uint8_t c1, std::int64_t t, std::int64_t n) {
  if (n == 0) return c0;
  return static_cast<std::uint8_t>(c0 + floor_div<std::int64_t>(2 * t * (int{c1} - int{c0}) + n, 2 * n));
}

template <int C>
void draw_line(const ScreenLine& line, PrimitivePlan mode, Image& image, Rect clip) {
  // Work in (u, v) = (major, minor) axis coordinates; geometry already made u0 <= u1.
  const bool x_major = line.x1 - line.x0 >= std::abs(line.y1 - line.y0);
  const std::int64_t u0 = x_major ? line.x0 : line.y0, u1 = x_major ? line.x1 : line.y1;
  const std::int64_t v0 = x_major ? line.y0 : line.x0, v1 = x_major ? line.y1 : line.x1;
  const std::int64_t du = u1 - u0, dv = v1 - v0;  // du >= |dv| >= 0
  const std::int64_t u_min = x_major ? clip.x0 : clip.y0, u_max = (x_major ? clip.x1 : clip.y1) - 1;
  const std::int64_t v_min = x_major ? clip.y0 : clip.x0, v_max = (x_major ? clip.y1 : clip.x1) - 1;

  // The Bresenham pixel of column u is the nearest row to the exact line, ties rounding up:
  // v(u) = v0 + floor((2 (u - u0) dv + du) / (2 du)). 128-bit: |u - u0|, |dv| reach 2^31.
  auto v_at = [&](std::int64_t u) -> std::int64_t {
    if (du == 0) return v0;
    const __int128 n = static_cast<__int128>(2 * (u - u0)) * dv + du;
    return v0 + static_cast<std::int64_t>(floor_div<__int128>(n, 2 * static_cast<__int128>(du)));
  };

  std::int64_t lo = std::max(u0 + (line.draw_first ? 0 : 1), u_min);
  std::int64_t hi = std::min(u1 - (line.draw_last ? 0 : 1), u_max);
  if (lo > hi) return;
  // v(u) is monotone, so the columns whose row is inside the clip form one interval: find its ends by
  // bisection. The cost is then the visible length, however far the endpoints lie outside.
  auto inside_v = [&](std::int64_t u) {
    const std::int64_t v = v_at(u);
    return v >= v_min && v <= v_max;
  };
  auto before_v = [&](std::int64_t u) {  // true while the line has not yet reached the clip rows
    const std::int64_t v = v_at(u);
    return dv >= 0 ? v < v_min : v > v_max;
  };
  {  // first u that is not before the clip rows
    std::int64_t a = lo, b = hi + 1;
    while (a < b) {
      const std::int64_t m = a + (b - a) / 2;
      if (before_v(m)) a = m + 1;
      else b = m;
    }
    lo = a;
  }
  if (lo > hi || !inside_v(lo)) return;
  {  // last u still inside the clip rows
    std::int64_t a = lo, b = hi;
    while (a < b) {
      const std::int64_t m = a + (b - a + 1) / 2;
      if (inside_v(m)) a = m;
      else b = m - 1;
    }
    hi = a;
  }

  // Incremental Bresenham from lo: v = v(lo), remainder r in [0, 2 du).
  std::int64_t v = v_at(lo);
  std::int64_t r = 0;
  if (du != 0) {
    const __int128 n = static_cast<__int128>(2 * (lo - u0)) * dv + du;
    r = static_cast<std::int64_t>(n - static_cast<__int128>(v - v0) * 2 * du);
  }
  const std::size_t stride_u = x_major ? C : static_cast<std::size_t>(image.width) * C;
  const std::size_t stride_v = x_major ? static_cast<std::size_t>(image.width) * C : C;
  for (std::int64_t u = lo; u <= hi; ++u) {
    Rgba8 c = line.c0;
    if (mode.smooth) {
      const std::int64_t t = u - u0;
      c = {lerp_channel(line.c0.r, line.c1.r, t, du), lerp_channel(line.c0.g, line.c1.g, t, du),
           lerp_channel(line.c0.b, line.c1.b, t, du), lerp_channel(line.c0.a, line.c1.a, t, du)};
    }
    std::uint8_t* p = image.pixels.data() + static_cast<std::size_t>(u) * stride_u + static_cast<std::size_t>(v) * stride_v;
    if (mode.blend) blend<C>(p, c);
    else store<C>(p, c);
    // step the minor axis when the remainder passes a half pixel
    r += 2 * dv;
    if (r >= 2 * du && du != 0) r -= 2 * du, ++v;
    else if (r < 0) r += 2 * du, --v;
  }
}

template <int C>
void draw_all(const DrawList& list, Image& image, Rect clip) {
  for (const DrawOp& op : list.ops) {
    if (op.kind == DrawOp::Kind::triangles) {
      for (std::uint32_t k = 0; k < op.count; ++k) fill_triangle<C>(list.triangles[op.first + k], op.mode, image, clip);
    } else {
      for (std::uint32_t k = 0; k < op.count; ++k) draw_line<C>(list.lines[op.first + k], op.mode, image, clip);
    }
  }
}

}  // namespace

void draw(const DrawList& list, Image& image, Rect clip) {
  switch (image.format) {
    case PixelFormat::grey8: return draw_all<1>(list, image, clip);
    case PixelFormat::grey_alpha8: return draw_all<2>(list, image, clip);
    case PixelFormat::rgb8: return draw_all<3>(list, image, clip);
    case PixelFormat::rgba8: return draw_all<4>(list, image, clip);
  }
}

}  // namespace raster::detail
