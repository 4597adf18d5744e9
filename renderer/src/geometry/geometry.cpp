#include "geometry/geometry.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "base/vecmath.h"

namespace raster::detail {
namespace {

// A 2D vertex carries its colour only (the plan gives 2D modes no other varying).
SetupVertex vertex_2d(const VaryingLayout& varyings, const Point2& p, Rgba8 c) {
  SetupVertex v;
  v.x = snap(p.x), v.y = snap(p.y);
  float* color = v.at(varyings, Varying::color);
  color[0] = c.r, color[1] = c.g, color[2] = c.b, color[3] = c.a;
  return v;
}

void add_triangle(const Scene& scene, const Primitive& prim, std::uint32_t call, Setup& setup) {
  const Point2* pts = &scene.points[prim.first_point];
  const VaryingLayout& with = setup.calls[call].layout;
  const SetupVertex v[3] = {vertex_2d(with, pts[0], scene.vertex_color(prim, 0)),
                            vertex_2d(with, pts[1], scene.vertex_color(prim, 1)),
                            vertex_2d(with, pts[2], scene.vertex_color(prim, 2))};
  setup.add_triangle(call, v);
}

void add_segment(const Scene& scene, const Primitive& prim, std::uint32_t i, std::uint32_t j, bool draw_first,
                 bool draw_last, std::uint32_t call, Setup& setup) {
  const Point2 a = scene.points[prim.first_point + i], b = scene.points[prim.first_point + j];
  LineRecord line;
  line.x0 = std::floor(a.x), line.y0 = std::floor(a.y), line.x1 = std::floor(b.x), line.y1 = std::floor(b.y);
  line.c0 = scene.vertex_color(prim, i), line.c1 = scene.vertex_color(prim, j);
  line.draw_first = draw_first, line.draw_last = draw_last;
  line.call = call;
  setup.add_line(line);
}

// A segment as the rectangle of its width around it (butt caps): how lines are drawn when anti-aliased or
// wider than one pixel. One quad record when the plan says so (flat colour, fast range) and the snapped
// corners make a convex quad; else two triangles with the endpoints' colours.
void add_segment_rectangle(const Scene& scene, const Primitive& prim, std::uint32_t i, std::uint32_t j,
                           const PrimitivePlan& mode, std::uint32_t call, Setup& setup) {
  const Point2 a = scene.points[prim.first_point + i], b = scene.points[prim.first_point + j];
  double x[4], y[4];
  if (!segment_rectangle(a.x, a.y, b.x, b.y, prim.width, x, y)) return;
  const Point2 q[4] = {{x[0], y[0]}, {x[1], y[1]}, {x[2], y[2]}, {x[3], y[3]}};
  const Rgba8 ca = scene.vertex_color(prim, i), cb = scene.vertex_color(prim, j);
  const Rgba8 c[4] = {ca, cb, cb, ca};
  const VaryingLayout& with = setup.calls[call].layout;
  if (mode.line_quads) {
    const SetupVertex corners[4] = {vertex_2d(with, q[0], c[0]), vertex_2d(with, q[1], c[1]),
                                    vertex_2d(with, q[2], c[2]), vertex_2d(with, q[3], c[3])};
    if (setup.add_quad(call, corners)) return;
  }
  for (const auto& t : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
    const SetupVertex v[3] = {vertex_2d(with, q[t[0]], c[t[0]]), vertex_2d(with, q[t[1]], c[t[1]]),
                              vertex_2d(with, q[t[2]], c[t[2]])};
    setup.add_triangle(call, v);
  }
}

// A polyline draws each joint pixel once (no double blending where segments meet); wide or anti-aliased
// ones are rectangles per segment. Triangle outlines are closed polylines.
void add_polyline(const Scene& scene, const Primitive& prim, bool closed, const PrimitivePlan& mode,
                  std::uint32_t call, Setup& setup) {
  const std::uint32_t n = prim.point_count;
  if (mode.line_rectangles) {
    for (std::uint32_t i = 0; i + 1 < n; ++i) add_segment_rectangle(scene, prim, i, i + 1, mode, call, setup);
    if (closed && n >= 3) add_segment_rectangle(scene, prim, n - 1, 0, mode, call, setup);
    return;
  }
  closed = closed && n >= 3;  // closing a 2-point polyline would draw its one segment twice
  for (std::uint32_t i = 0; i + 1 < n; ++i) add_segment(scene, prim, i, i + 1, i == 0, true, call, setup);
  if (closed) add_segment(scene, prim, n - 1, 0, false, false, call, setup);
}

// A shader: a call of its own and the rectangle of pixels it writes as one quad record, binned to the tiles
// it reaches like any other (its program is run by shade/, not by the quad's coverage).
void add_program(const ShaderPlan& p, const DrawPlan& draw, Setup& setup) {
  DrawCall call = make_call(draw.mode);
  call.shader = draw.shader;
  const std::uint32_t index = setup.add_call(call);
  const double x[4] = {double(p.x0), double(p.x1), double(p.x1), double(p.x0)};
  const double y[4] = {double(p.y0), double(p.y0), double(p.y1), double(p.y1)};
  SetupVertex v[4];
  for (int k = 0; k < 4; ++k) {
    v[k].x = x[k] * kSubpixelScale, v[k].y = y[k] * kSubpixelScale;
    std::fill(std::begin(v[k].values), std::end(v[k].values), 0.0f);
  }
  setup.add_quad(index, v);
}

}  // namespace

Setup build_setup(const Scene& scene, const RenderPlan& plan, StopMeter& meter) {
  Setup setup;
  setup.width = plan.width, setup.height = plan.height;
  setup.centre_samples = plan.coverage == Coverage::centre;
  if (multisampled(plan.coverage)) {
    setup.pattern = sample_pattern(plan.samples).data();
    setup.pattern_size = plan.samples;
  }
  Records& first = setup.last_part();  // a record per 2D primitive, about: sized once
  first.order.reserve(plan.draws.size()), first.triangles.reserve(plan.draws.size());
  for (const DrawPlan& draw : plan.draws) {
    if (meter.add(StopMeter::kPrimitiveWork)) break;
    const Primitive& prim = scene.primitives[draw.primitive];
    if (prim.kind == PrimitiveKind::mesh) {
      add_mesh(scene.meshes[prim.mesh], draw, plan, setup, meter);
      continue;
    }
    if (prim.kind == PrimitiveKind::shader) {
      add_program(plan.shaders[static_cast<std::size_t>(draw.shader)], draw, setup);
      continue;
    }
    // Consecutive primitives drawn the same way share one call; a union-coverage primitive has its own,
    // which is how the tiles know where its accumulation ends.
    if (setup.calls.empty() || !(setup.calls.back().mode == draw.mode) || draw.mode.union_coverage)
      setup.add_call(make_call(draw.mode));
    const auto call = static_cast<std::uint32_t>(setup.calls.size() - 1);
    if (prim.kind == PrimitiveKind::triangle && prim.fill)
      add_triangle(scene, prim, call, setup);
    else
      add_polyline(scene, prim, prim.kind == PrimitiveKind::triangle || prim.closed, draw.mode, call, setup);
  }
  return setup;
}

MaterialCalls add_material_calls(const Mesh& mesh, const ViewPlan& view, bool textured,
                                 const std::vector<const MipChain*>& chains, DrawCall call, Setup& setup) {
  MaterialCalls calls;
  const Vec3 toward = normalize(view.eye - view.target);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::int32_t texture = !textured ? -1 : mesh.face_textures.empty() ? 0 : mesh.face_textures[t];
    const auto [it, is_new] = calls.try_emplace(material_key(mesh, t, texture), 0);
    if (!is_new) continue;
    const auto material = static_cast<std::int32_t>(it->first & 0xffffffff) - 1;
    call.texture = texture >= 0 ? chains[static_cast<std::size_t>(texture)] : nullptr;
    call.specular = Specular{};  // a face without a material: Lambert, per pixel
    if (material >= 0) {
      const Material& m = mesh.materials[static_cast<std::size_t>(material)];
      Specular& s = call.specular;
      if (m.is_specular()) s.model = m.model;
      s.metallic = m.metallic, s.roughness = m.roughness;
      if (m.metallic_roughness_texture >= 0 && textured)
        s.metallic_roughness = chains[static_cast<std::size_t>(m.metallic_roughness_texture)];
      for (int c = 0; c < 3; ++c) s.specular[c] = m.specular[c];
      s.shininess = static_cast<int>(std::lround(std::clamp(m.shininess, 0.0f, 1000.0f)));
      s.orthographic = view.projection == Projection::orthographic;
      const double eye[3] = {view.eye.x, view.eye.y, view.eye.z}, to[3] = {toward.x, toward.y, toward.z};
      for (int c = 0; c < 3; ++c)
        s.eye[c] = static_cast<float>(eye[c]), s.toward_eye[c] = static_cast<float>(to[c]);
    }
    it->second = setup.add_call(call);
  }
  return calls;
}

}  // namespace raster::detail
