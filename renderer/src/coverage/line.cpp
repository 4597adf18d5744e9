#include "coverage/line.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

#include "shade/pixel.h"
#include "base/wide.h"

namespace raster::detail {
namespace {

// ---- Lines: symmetric Bresenham, clipped before stepping ------------------------------------------------

// T is __int128 for endpoints within 2^60 px (every product below fits), Wide beyond.
template <int C, typename T>
void draw_line(const LineRecord& line, PrimitivePlan mode, const Surface& surface, Rect clip) {
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

  // Writes one pixel; 3D lines first pass the depth test (reversed: larger is nearer).
  auto plot = [&](std::int64_t u, std::int64_t v, float z, auto&& color) {
    const int x = static_cast<int>(x_major ? u : v), y = static_cast<int>(x_major ? v : u);
    const std::size_t index = surface.index(x, y);
    if (mode.depth) {
      if (!(z > surface.depth[index])) return;
      surface.depth[index] = z;
    }
    std::uint8_t* p = surface.color + index * C;
    const Rgba8 c = mode.smooth ? color() : c0;
    put<C>(p, c, mode.blend);
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

bool line_fits_int128(const LineRecord& l) {
  constexpr double kLimit = 0x1p60;  // keeps 2 dv (u - u0) + 2 du v0 below 2^125
  return std::fabs(l.x0) <= kLimit && std::fabs(l.y0) <= kLimit && std::fabs(l.x1) <= kLimit &&
         std::fabs(l.y1) <= kLimit;
}

// A 1-px line steps one pixel per column (or row) of its longer axis, clipped to the tile first.
std::int64_t line_work(const LineRecord& l, Rect clip) {
  const double steps = std::max(std::fabs(l.x1 - l.x0), std::fabs(l.y1 - l.y0));  // pixels
  const double most = std::max(clip.x1 - clip.x0, clip.y1 - clip.y0);
  return 1 + static_cast<std::int64_t>(std::min(steps, most));
}

template <int C>
void draw_line_in(const LineRecord& line, const PrimitivePlan& mode, const Surface& surface, Rect clip) {
  if (line_fits_int128(line))
    draw_line<C, __int128>(line, mode, surface, clip);
  else
    draw_line<C, Wide>(line, mode, surface, clip);
}

}  // namespace

void draw_line(const LineRecord& line, const PrimitivePlan& mode, const Surface& surface, Rect clip,
               StopMeter& meter) {
  switch (surface.channels) {
    case 1:
      draw_line_in<1>(line, mode, surface, clip);
      break;
    case 2:
      draw_line_in<2>(line, mode, surface, clip);
      break;
    case 3:
      draw_line_in<3>(line, mode, surface, clip);
      break;
    default:
      draw_line_in<4>(line, mode, surface, clip);
      break;
  }
  meter.add(line_work(line, clip));
}

}  // namespace raster::detail
