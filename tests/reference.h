// A deliberately simple reference rasterizer: every pixel of the image is tested on its own with exact
// integer arithmetic on the snapped 1/256 grid, and the top-left rule is written out the way the D3D
// documentation states it. Slow and obviously right; the production rasterizer is diffed against it.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

namespace ref {

using i128 = __int128;

/// Snap to 1/256 px, rounding half up (the rule the scene format documents).
inline std::int64_t snap(double px) {
  return static_cast<std::int64_t>(std::floor(px * 256.0 + 0.5));
}

struct V {
  std::int64_t x, y;  // 1/256 px
};

/// Twice the signed area of (a, b, p) in y-down coordinates; > 0 when p is on the interior side of a->b
/// for a triangle whose vertices are ordered so that this is positive at the third vertex.
inline i128 orient(V a, V b, V p) {
  return static_cast<i128>(b.x - a.x) * (p.y - a.y) - static_cast<i128>(b.y - a.y) * (p.x - a.x);
}

/// "A top edge is an edge that is exactly horizontal and above the other edges" (y down: the third
/// vertex has a larger y). "A left edge is an edge that is not exactly horizontal and is on the left side
/// of the triangle": the third vertex lies strictly to its right at the third vertex's height.
inline bool is_top_left(V a, V b, V third) {
  if (a.y == b.y) return third.y > a.y;
  // x of the edge's line at y = third.y, compared with third.x, without division:
  // third.x > a.x + (third.y - a.y) (b.x - a.x) / (b.y - a.y)
  const i128 lhs = static_cast<i128>(third.x - a.x) * (b.y - a.y);
  const i128 rhs = static_cast<i128>(third.y - a.y) * (b.x - a.x);
  return (b.y - a.y) > 0 ? lhs > rhs : lhs < rhs;
}

/// Coverage of a triangle given in pixels: mask[y * w + x] = 1 where pixel (x, y)'s centre is covered.
/// Also returns, per covered pixel, the three exact barycentric weights (as doubles) when asked.
struct Coverage {
  std::vector<std::uint8_t> mask;
  std::vector<double> bary;  // 3 per pixel, only for covered pixels (others 0)
};

inline Coverage triangle(double ax, double ay, double bx, double by, double cx, double cy, int w, int h) {
  Coverage out;
  out.mask.assign(static_cast<std::size_t>(w) * h, 0);
  out.bary.assign(static_cast<std::size_t>(w) * h * 3, 0.0);
  V v[3] = {{snap(ax), snap(ay)}, {snap(bx), snap(by)}, {snap(cx), snap(cy)}};
  const i128 area = orient(v[0], v[1], v[2]);
  if (area == 0) return out;
  if (area < 0) std::swap(v[1], v[2]);
  const i128 a2 = area < 0 ? -area : area;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const V p{x * 256 + 128, y * 256 + 128};
      bool inside = true;
      i128 e[3];
      for (int k = 0; k < 3; ++k) {
        const V a = v[(k + 1) % 3], b = v[(k + 2) % 3], third = v[k];
        e[k] = orient(a, b, p);  // vertex k's weight times a2
        inside = inside && (e[k] > 0 || (e[k] == 0 && is_top_left(a, b, third)));
      }
      if (!inside) continue;
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      out.mask[i] = 1;
      for (int k = 0; k < 3; ++k) out.bary[i * 3 + k] = static_cast<double>(e[k]) / static_cast<double>(a2);
    }
  }
  // Weights belong to the caller's vertex order; undo the swap.
  if (area < 0)
    for (std::size_t i = 0; i < out.mask.size(); ++i) std::swap(out.bary[i * 3 + 1], out.bary[i * 3 + 2]);
  return out;
}

/// The pixels of a 1-px line between the pixels containing a and b: along the major axis (x when
/// |dx| >= |dy|) every column from one end to the other, in the row nearest the exact line through the
/// two pixel centres, ties toward larger rows. Endpoints are ordered so the major coordinate increases.
inline std::vector<std::uint8_t> line(double ax, double ay, double bx, double by, int w, int h) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(w) * h, 0);
  std::int64_t x0 = static_cast<std::int64_t>(std::floor(ax)), y0 = static_cast<std::int64_t>(std::floor(ay));
  std::int64_t x1 = static_cast<std::int64_t>(std::floor(bx)), y1 = static_cast<std::int64_t>(std::floor(by));
  const bool x_major = std::llabs(x1 - x0) >= std::llabs(y1 - y0);
  if (!x_major) std::swap(x0, y0), std::swap(x1, y1);
  if (x1 < x0 || (x1 == x0 && y1 < y0)) std::swap(x0, x1), std::swap(y0, y1);
  for (std::int64_t u = x0; u <= x1; ++u) {
    std::int64_t v = y0;
    if (x1 != x0) {
      // exact row: y0 + (u - x0) (y1 - y0) / (x1 - x0); nearest, ties up: floor(exact + 1/2)
      const i128 num = static_cast<i128>(2 * (u - x0)) * (y1 - y0) + (x1 - x0);
      const i128 den = 2 * static_cast<i128>(x1 - x0);
      i128 q = num / den;
      if (num % den != 0 && num < 0) --q;
      v = y0 + static_cast<std::int64_t>(q);
    }
    const std::int64_t px = x_major ? u : v, py = x_major ? v : u;
    if (px >= 0 && px < w && py >= 0 && py < h) mask[static_cast<std::size_t>(py) * w + px] = 1;
  }
  return mask;
}

}  // namespace ref
