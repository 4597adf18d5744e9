#include "geometry.h"

#include <array>
#include <cmath>

namespace raster::detail {
namespace {

bool in_fast_range(const Point2& p) {
  return std::fabs(p.x) <= kFastRangePx && std::fabs(p.y) <= kFastRangePx;
}

void add_triangle(const Scene& scene, const Primitive& prim, DrawList& list, DrawOp& op) {
  const Point2* pts = &scene.points[prim.first_point];
  if (in_fast_range(pts[0]) && in_fast_range(pts[1]) && in_fast_range(pts[2])) {
    op.kind = DrawOp::Kind::triangles;
    op.first = static_cast<std::uint32_t>(list.triangles.size());
    ScreenTriangle t;
    for (std::uint32_t k = 0; k < 3; ++k)
      t.v[k] = {static_cast<std::int32_t>(snap(pts[k].x)), static_cast<std::int32_t>(snap(pts[k].y)),
                scene.vertex_color(prim, k)};
    list.triangles.push_back(t);
  } else {
    op.kind = DrawOp::Kind::huge_triangles;
    op.first = static_cast<std::uint32_t>(list.huge_triangles.size());
    HugeTriangle t;
    for (std::uint32_t k = 0; k < 3; ++k) {
      t.x[k] = snap(pts[k].x);
      t.y[k] = snap(pts[k].y);
      t.color[k] = scene.vertex_color(prim, k);
    }
    list.huge_triangles.push_back(t);
  }
  op.count = 1;
}

void add_segment(const Scene& scene, const Primitive& prim, std::uint32_t i, std::uint32_t j, bool draw_first,
                 bool draw_last, std::vector<ScreenLine>& out) {
  const Point2 a = scene.points[prim.first_point + i], b = scene.points[prim.first_point + j];
  out.push_back({std::floor(a.x), std::floor(a.y), std::floor(b.x), std::floor(b.y),
                 scene.vertex_color(prim, i), scene.vertex_color(prim, j), draw_first, draw_last});
}

// A segment as the rectangle of its width around it (butt caps), two triangles with the endpoints'
// colours: how lines are drawn when anti-aliased or wider than one pixel.
void add_segment_rectangle(const Scene& scene, const Primitive& prim, std::uint32_t i, std::uint32_t j,
                           DrawList& list) {
  const Point2 a = scene.points[prim.first_point + i], b = scene.points[prim.first_point + j];
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
  if (!(len > 0) || !std::isfinite(len)) return;  // a point, or a segment too long to have a direction
  const double half = prim.width * 0.5, nx = -dy / len * half, ny = dx / len * half;
  const Point2 q[4] = {
      {a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny}};
  const Rgba8 ca = scene.vertex_color(prim, i), cb = scene.vertex_color(prim, j);
  const Rgba8 c[4] = {ca, cb, cb, ca};
  for (const auto& t : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
    const Point2 p[3] = {q[t[0]], q[t[1]], q[t[2]]};
    if (in_fast_range(p[0]) && in_fast_range(p[1]) && in_fast_range(p[2])) {
      ScreenTriangle tri;
      for (int k = 0; k < 3; ++k)
        tri.v[k] = {static_cast<std::int32_t>(snap(p[k].x)), static_cast<std::int32_t>(snap(p[k].y)),
                    c[t[k]]};
      list.triangles.push_back(tri);
    } else {
      HugeTriangle tri;
      for (int k = 0; k < 3; ++k) tri.x[k] = snap(p[k].x), tri.y[k] = snap(p[k].y), tri.color[k] = c[t[k]];
      list.huge_triangles.push_back(tri);
    }
  }
}

// Wide or anti-aliased lines: every segment a rectangle; fast and huge triangles go to their own ops.
void add_polyline_rectangles(const Scene& scene, const Primitive& prim, bool closed,
                             const PrimitivePlan& mode, DrawList& list) {
  const std::uint32_t n = prim.point_count;
  const std::size_t t0 = list.triangles.size(), h0 = list.huge_triangles.size();
  for (std::uint32_t i = 0; i + 1 < n; ++i) add_segment_rectangle(scene, prim, i, i + 1, list);
  if (closed && n >= 3) add_segment_rectangle(scene, prim, n - 1, 0, list);
  DrawOp op;
  op.mode = mode;
  op.mode.smooth = true;  // endpoint colours may differ; equal ones interpolate to themselves exactly
  if (list.triangles.size() > t0)
    list.ops.push_back({DrawOp::Kind::triangles, op.mode, static_cast<std::uint32_t>(t0),
                        static_cast<std::uint32_t>(list.triangles.size() - t0)});
  if (list.huge_triangles.size() > h0)
    list.ops.push_back({DrawOp::Kind::huge_triangles, op.mode, static_cast<std::uint32_t>(h0),
                        static_cast<std::uint32_t>(list.huge_triangles.size() - h0)});
}

// A polyline draws each joint pixel once (no double blending where segments meet). Triangle outlines
// are closed polylines.
void add_polyline(const Scene& scene, const Primitive& prim, bool closed, DrawList& list, DrawOp& op) {
  op.kind = DrawOp::Kind::lines;
  op.first = static_cast<std::uint32_t>(list.lines.size());
  const std::uint32_t n = prim.point_count;
  closed = closed && n >= 3;  // closing a 2-point polyline would draw its one segment twice
  for (std::uint32_t i = 0; i + 1 < n; ++i) add_segment(scene, prim, i, i + 1, i == 0, true, list.lines);
  if (closed) add_segment(scene, prim, n - 1, 0, false, false, list.lines);
  op.count = static_cast<std::uint32_t>(list.lines.size()) - op.first;
}

}  // namespace

double snap(double px) {
  const double units = px * static_cast<double>(kSubpixelScale);  // exact: a power-of-two scale
  // From 2^52 up every double is already an integer; adding 0.5 there would round to even instead.
  return std::fabs(units) >= 0x1p52 ? units : std::floor(units + 0.5);
}

DrawList build_draw_list(const Scene& scene, const RenderPlan& plan, StopMeter& meter) {
  DrawList list;
  if (plan.depth_buffer) {
    list.to_light[0] = plan.view.to_light.x, list.to_light[1] = plan.view.to_light.y,
    list.to_light[2] = plan.view.to_light.z;
    list.ambient = plan.view.ambient;
  }
  list.ops.reserve(scene.primitives.size() - static_cast<std::size_t>(plan.culled_count));
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    if (meter.add(StopMeter::kPrimitiveWork)) break;
    const PrimitivePlan& mode = plan.primitives[i];
    if (!mode.visible) continue;
    const Primitive& prim = scene.primitives[i];
    if (prim.kind == PrimitiveKind::mesh) {
      add_mesh(scene.meshes[prim.mesh], mode, plan, list, meter);
      continue;
    }
    DrawOp op;
    op.mode = mode;
    const bool closed = prim.kind == PrimitiveKind::triangle || prim.closed;
    if (prim.kind == PrimitiveKind::triangle && prim.fill) {
      add_triangle(scene, prim, list, op);
    } else if (mode.line_rectangles) {
      add_polyline_rectangles(scene, prim, closed, mode, list);
      continue;
    } else {
      add_polyline(scene, prim, closed, list, op);
    }
    if (op.count > 0) list.ops.push_back(op);
  }
  return list;
}

}  // namespace raster::detail
