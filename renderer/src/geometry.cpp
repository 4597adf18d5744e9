#include "geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

namespace raster::detail {
namespace {

// A vertex during guard-band clipping: position in pixels, colour in 0..255 as doubles so that clipped
// colours are interpolated without intermediate rounding.
struct ClipVertex {
  double x, y;
  std::array<double, 4> c;
};

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t) {
  ClipVertex r;
  r.x = a.x + (b.x - a.x) * t;
  r.y = a.y + (b.y - a.y) * t;
  for (int k = 0; k < 4; ++k) r.c[k] = a.c[k] + (b.c[k] - a.c[k]) * t;
  return r;
}

// Signed distance to one guard-band side: >= 0 is inside. axis 0 = x, 1 = y; sign +1 keeps v >= -G,
// sign -1 keeps v <= G.
double inside_distance(const ClipVertex& v, int axis, double sign) {
  const double value = axis == 0 ? v.x : v.y;
  return sign * value + kGuardBandPx;
}

// Intersection of segment a-b with a side. Computed from the endpoints in a canonical order, so the two
// triangles that share an edge get bit-identical points and the shared edge stays watertight.
ClipVertex intersect(const ClipVertex& a, const ClipVertex& b, int axis, double sign) {
  const bool swap = std::tie(b.x, b.y) < std::tie(a.x, a.y);
  const ClipVertex& p = swap ? b : a;
  const ClipVertex& q = swap ? a : b;
  const double dp = inside_distance(p, axis, sign), dq = inside_distance(q, axis, sign);
  ClipVertex r = lerp(p, q, dp / (dp - dq));
  // Land exactly on the side; the division can leave it a rounding error outside.
  (axis == 0 ? r.x : r.y) = -sign * kGuardBandPx;
  return r;
}

// Sutherland-Hodgman against the four guard-band sides. A triangle has at most 7 vertices afterwards.
int clip_to_guard_band(std::array<ClipVertex, 9>& poly, int n) {
  std::array<ClipVertex, 9> out;
  for (int axis = 0; axis < 2; ++axis) {
    for (double sign : {1.0, -1.0}) {
      int m = 0;
      for (int i = 0; i < n; ++i) {
        const ClipVertex& a = poly[i];
        const ClipVertex& b = poly[(i + 1) % n];
        const bool a_in = inside_distance(a, axis, sign) >= 0, b_in = inside_distance(b, axis, sign) >= 0;
        if (a_in) out[m++] = a;
        if (a_in != b_in) out[m++] = intersect(a, b, axis, sign);
      }
      poly = out;
      n = m;
      if (n < 3) return 0;
    }
  }
  return n;
}

std::uint8_t to_byte(double v) { return static_cast<std::uint8_t>(std::clamp(std::floor(v + 0.5), 0.0, 255.0)); }

ScreenVertex to_screen(const ClipVertex& v) {
  return {snap(v.x), snap(v.y), Rgba8{to_byte(v.c[0]), to_byte(v.c[1]), to_byte(v.c[2]), to_byte(v.c[3])}};
}

bool in_guard_band(const Point2& p) { return std::fabs(p.x) <= kGuardBandPx && std::fabs(p.y) <= kGuardBandPx; }

void add_triangle(const Scene& scene, const Primitive& prim, std::vector<ScreenTriangle>& out) {
  const Point2* pts = &scene.points[prim.first_point];
  if (in_guard_band(pts[0]) && in_guard_band(pts[1]) && in_guard_band(pts[2])) {
    ScreenTriangle t;
    for (int k = 0; k < 3; ++k) t.v[k] = {snap(pts[k].x), snap(pts[k].y), scene.vertex_color(prim, k)};
    out.push_back(t);
    return;
  }
  // Rare path: a vertex beyond the guard band. Clip in double, then fan-triangulate the polygon; the fan's
  // inner edges are shared between its own triangles, so the top-left rule covers them once.
  std::array<ClipVertex, 9> poly;
  for (int k = 0; k < 3; ++k) {
    const Rgba8 c = scene.vertex_color(prim, k);
    poly[k] = {pts[k].x, pts[k].y, {double(c.r), double(c.g), double(c.b), double(c.a)}};
  }
  const int n = clip_to_guard_band(poly, 3);
  for (int i = 1; i + 1 < n; ++i) out.push_back({{to_screen(poly[0]), to_screen(poly[i]), to_screen(poly[i + 1])}});
}

// Cuts the real segment a-b to the +-kLineRangePx box (Liang-Barsky). Returns false when nothing is left.
bool cut_to_line_range(Point2& a, Point2& b) {
  // Canonical direction, so a-b and b-a are cut to the same points.
  const bool swap = std::tie(b.x, b.y) < std::tie(a.x, a.y);
  if (swap) std::swap(a, b);
  double t0 = 0, t1 = 1;
  const double d[2] = {b.x - a.x, b.y - a.y};
  const double s[2] = {a.x, a.y};
  for (int axis = 0; axis < 2; ++axis) {
    for (double sign : {1.0, -1.0}) {
      // inside: sign * (s + t d) <= R
      const double num = kLineRangePx - sign * s[axis], den = sign * d[axis];
      if (den == 0) {
        if (num < 0) return false;
      } else if (den > 0) {
        t1 = std::min(t1, num / den);
      } else {
        t0 = std::max(t0, num / den);
      }
    }
  }
  if (t0 > t1) return false;
  const Point2 a0 = a;
  if (t0 > 0) a = {a0.x + t0 * d[0], a0.y + t0 * d[1]};
  if (t1 < 1) b = {a0.x + t1 * d[0], a0.y + t1 * d[1]};
  if (swap) std::swap(a, b);
  return true;
}

std::int64_t pixel_index(double v) {
  return static_cast<std::int64_t>(std::floor(std::clamp(v, -kLineRangePx, kLineRangePx)));
}

// Appends the segment between points i and j (vertex indices within the primitive).
void add_segment(const Scene& scene, const Primitive& prim, std::uint32_t i, std::uint32_t j, bool draw_first,
                 bool draw_last, std::vector<ScreenLine>& out) {
  Point2 a = scene.points[prim.first_point + i], b = scene.points[prim.first_point + j];
  const bool in_range = std::fabs(a.x) <= kLineRangePx && std::fabs(a.y) <= kLineRangePx &&
                        std::fabs(b.x) <= kLineRangePx && std::fabs(b.y) <= kLineRangePx;
  if (!in_range && !cut_to_line_range(a, b)) return;
  ScreenLine l{pixel_index(a.x), pixel_index(a.y), pixel_index(b.x), pixel_index(b.y),
               scene.vertex_color(prim, i), scene.vertex_color(prim, j), draw_first, draw_last};
  const std::int64_t dx = l.x1 - l.x0, dy = l.y1 - l.y0;
  const bool x_major = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
  const bool reverse = x_major ? (dx < 0 || (dx == 0 && dy < 0)) : dy < 0;
  if (reverse) {
    std::swap(l.x0, l.x1);
    std::swap(l.y0, l.y1);
    std::swap(l.c0, l.c1);
    std::swap(l.draw_first, l.draw_last);
  }
  out.push_back(l);
}

// A polyline draws each joint pixel once (no double blending where segments meet).
void add_polyline(const Scene& scene, const Primitive& prim, bool closed, std::vector<ScreenLine>& out) {
  const std::uint32_t n = prim.point_count;
  closed = closed && n >= 3;  // closing a 2-point polyline would draw its one segment twice
  for (std::uint32_t i = 0; i + 1 < n; ++i) add_segment(scene, prim, i, i + 1, i == 0, true, out);
  if (closed) add_segment(scene, prim, n - 1, 0, false, false, out);
}

}  // namespace

std::int32_t snap(double px) {
  return static_cast<std::int32_t>(std::floor(px * static_cast<double>(kSubpixelScale) + 0.5));
}

DrawList build_draw_list(const Scene& scene, const RenderPlan& plan) {
  DrawList list;
  list.ops.reserve(scene.primitives.size() - static_cast<std::size_t>(plan.culled_count));
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const PrimitivePlan& mode = plan.primitives[i];
    if (!mode.visible) continue;
    const Primitive& prim = scene.primitives[i];
    DrawOp op;
    op.mode = mode;
    if (prim.kind == PrimitiveKind::triangle && prim.fill) {
      op.kind = DrawOp::Kind::triangles;
      op.first = static_cast<std::uint32_t>(list.triangles.size());
      add_triangle(scene, prim, list.triangles);
      op.count = static_cast<std::uint32_t>(list.triangles.size()) - op.first;
    } else {
      op.kind = DrawOp::Kind::lines;
      op.first = static_cast<std::uint32_t>(list.lines.size());
      const bool closed = prim.kind == PrimitiveKind::triangle || prim.closed;
      add_polyline(scene, prim, closed, list.lines);
      op.count = static_cast<std::uint32_t>(list.lines.size()) - op.first;
    }
    if (op.count > 0) list.ops.push_back(op);
  }
  return list;
}

}  // namespace raster::detail
