#include "coverage/line.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

#include "base/wide.h"
#include "framebuffer/pixel.h"

namespace raster::detail {
namespace {

// ---- Lines: symmetric Bresenham, clipped before stepping ------------------------------------------------

template <typename T>
T to_t(double v) {
  if constexpr (std::is_same_v<T, Wide>)
    return Wide::from_double(v);
  else
    return static_cast<T>(v);
}

template <typename T>
std::int64_t to_i64(const T& v) {
  if constexpr (std::is_same_v<T, Wide>)
    return v.low64();
  else
    return static_cast<std::int64_t>(v);
}

// A line record in canonical order, on its major axis u (x when |dx| >= |dy|) and minor axis v: the first
// endpoint has the smaller u (then v), decided exactly, so a->b and b->a become the same line, hence the
// same pixels. Endpoint attributes are swapped with their endpoints.
template <typename T>
struct Span {
  T u0, v0, u1, v1;            ///< endpoints, pixel indices on the major (u) and minor (v) axis; u0 <= u1
  Rgba8 c0, c1;                ///< colours at (u0, v0) and (u1, v1)
  float z0, z1;                ///< 3D lines: z / w at each endpoint, reversed
  bool draw_first, draw_last;  ///< whether (u0, v0) / (u1, v1) is this line's pixel (LineRecord)
  bool x_major;                ///< u is x (|dx| >= |dy|); else u is y
};

template <typename T>
Span<T> canonical(const LineRecord& line) {
  Span<T> s{to_t<T>(line.x0), to_t<T>(line.y0), to_t<T>(line.x1), to_t<T>(line.y1), line.c0, line.c1,
            line.depth0,      line.depth1,      line.draw_first,  line.draw_last,   false};
  auto abs_t = [](const T& v) { return v < T(0) ? -v : v; };
  s.x_major = !(abs_t(s.u1 - s.u0) < abs_t(s.v1 - s.v0));
  if (!s.x_major) std::swap(s.u0, s.v0), std::swap(s.u1, s.v1);
  if (s.u1 < s.u0 || (s.u1 == s.u0 && s.v1 < s.v0)) {
    std::swap(s.u0, s.u1), std::swap(s.v0, s.v1), std::swap(s.c0, s.c1), std::swap(s.draw_first, s.draw_last);
    std::swap(s.z0, s.z1);
  }
  return s;
}

// The Bresenham row of column u is the one nearest the exact line through the two pixel centres, ties
// toward larger v: v(u) = floor(N(u) / 2du) with N(u) = 2 (u - u0) dv + du + 2 du v0. Rows outside the
// clip rows [v_min, v_max] are reported as v_min - 1 or v_max + 1: only whether they are inside matters
// there.
template <typename T>
struct Rows {
  const T& u0;                ///< the span's first column
  T two_du, two_dv, base;     ///< 2 du, 2 dv and du + 2 du v0: N(u) = two_dv (u - u0) + base
  std::int64_t v_min, v_max;  ///< the clip's rows on the minor axis, inclusive
  Rows(const Span<T>& s, const T& du, const T& dv, std::int64_t v_lo, std::int64_t v_hi)
      : u0(s.u0), two_du(du + du), two_dv(dv + dv), base(du + two_du * s.v0), v_min(v_lo), v_max(v_hi) {}
  T numerator(std::int64_t u) const { return two_dv * (T(u) - u0) + base; }
  std::int64_t at(std::int64_t u) const {
    return floor_div_clamped(numerator(u), two_du, v_min - 1, v_max + 1);
  }
};

// Narrows the columns [lo, hi] to those whose row is inside the clip rows. v(u) is monotone, so they form
// one interval: its ends are found by bisection, and the cost is then the visible length, however far the
// endpoints lie outside. False when no column is left.
template <typename T>
bool clip_columns(const Rows<T>& rows, bool rising, std::int64_t& lo, std::int64_t& hi) {
  {  // first column that has reached the clip rows
    std::int64_t a = lo, b = hi + 1;
    while (a < b) {
      const std::int64_t m = a + (b - a) / 2;
      const std::int64_t v = rows.at(m);
      if (rising ? v < rows.v_min : v > rows.v_max)
        a = m + 1;
      else
        b = m;
    }
    lo = a;
  }
  auto inside = [&](std::int64_t u) {
    const std::int64_t v = rows.at(u);
    return v >= rows.v_min && v <= rows.v_max;
  };
  if (lo > hi || !inside(lo)) return false;
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
  return true;
}

// T is __int128 for endpoints within 2^60 px (every product below fits), Wide beyond.
template <int C, typename T>
void draw_line(const LineRecord& line, PrimitivePlan mode, const Surface& surface, Rect clip) {
  const Span<T> s = canonical<T>(line);
  const T u0 = s.u0, u1 = s.u1, v0 = s.v0, v1 = s.v1;  // copies: the stepping loop keeps them in registers
  const Rgba8 c0 = s.c0, c1 = s.c1;
  const float z0 = s.z0, z1 = s.z1;
  const bool x_major = s.x_major;
  const T du = u1 - u0, dv = v1 - v0;  // du >= |dv| >= 0
  const std::int64_t u_min = x_major ? clip.x0 : clip.y0, u_max = (x_major ? clip.x1 : clip.y1) - 1;
  const std::int64_t v_min = x_major ? clip.y0 : clip.x0, v_max = (x_major ? clip.y1 : clip.x1) - 1;

  // Visible columns: [u0, u1] minus the joint pixels owned by neighbouring segments, within the clip.
  const T first = s.draw_first ? u0 : u0 + T(1), last = s.draw_last ? u1 : u1 - T(1);
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
  const Rows<T> rows(s, du, dv, v_min, v_max);
  if (!clip_columns(rows, !(dv < T(0)), lo, hi)) return;

  // Incremental Bresenham from lo: row v and remainder r = N(u) - 2du v in [0, 2du).
  const T two_du = rows.two_du, two_dv = rows.two_dv;
  std::int64_t v = rows.at(lo);
  T r = rows.numerator(lo) - two_du * T(v);
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
