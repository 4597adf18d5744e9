// Geometry for 3D content: model -> world -> clip space, lighting of flat faces, homogeneous clipping,
// perspective divide, viewport and snapping. Produces the same triangle records the 2D path does.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <tuple>

#include "base/memory.h"
#include "base/parallel.h"
#include "base/vecmath.h"
#include "geometry/geometry.h"
#include "geometry/normals.h"
#include "shade/light.h"
#include "shade/pixel.h"  // to_byte: a line's endpoint colours become bytes as pixels do

namespace raster::detail {
namespace {

/// The one vertex record of the 3D path: clip-space position plus the values of its primitive's varyings,
/// laid out as a SetupVertex's (raster/plan.h: VaryingLayout), so clipping interpolates them all with one
/// routine and a projected vertex takes them as they are.
struct ClipVertex {
  double x = 0, y = 0, z = 0, w = 0;  ///< clip space (see ViewPlan)
  float values[VaryingLayout::kMaxFloats] =
      {};  ///< at VaryingLayout::vertex_offset; depth and 1/w not yet written
};

/// a + (b - a) t, position and the first `floats` values (VaryingLayout::clipped_floats).
ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t, int floats) {
  ClipVertex r;
  r.x = a.x + (b.x - a.x) * t, r.y = a.y + (b.y - a.y) * t, r.z = a.z + (b.z - a.z) * t,
  r.w = a.w + (b.w - a.w) * t;
  for (int k = 0; k < floats; ++k)
    r.values[k] = static_cast<float>(a.values[k] + (b.values[k] - a.values[k]) * t);
  return r;
}

/// Six planes, each a linear function of (x, y, z, w) that is >= 0 inside: near (z <= w), far (z >= 0) and
/// the guard band |x|, |y| <= g w, which keeps snapped coordinates within +-(image + 8192 px).
struct Planes {
  double gx = 1, gy = 1;
  double distance(const ClipVertex& v, int plane) const {
    switch (plane) {
      case 0:
        return v.w - v.z;
      case 1:
        return v.z;
      case 2:
        return gx * v.w + v.x;
      case 3:
        return gx * v.w - v.x;
      case 4:
        return gy * v.w + v.y;
      default:
        return gy * v.w - v.y;
    }
  }
};
constexpr int kPlaneCount = 6;
constexpr double kGuardPx = 8192;

// The crossing of segment a-b with a plane, computed from the endpoints in a canonical order so that two
// triangles sharing the edge get bit-identical vertices and the edge stays watertight.
ClipVertex intersect(const ClipVertex& a, const ClipVertex& b, int plane, const Planes& planes, int floats) {
  const bool swap = std::tie(b.x, b.y, b.z, b.w) < std::tie(a.x, a.y, a.z, a.w);
  const ClipVertex& p = swap ? b : a;
  const ClipVertex& q = swap ? a : b;
  const double dp = planes.distance(p, plane), dq = planes.distance(q, plane);
  return lerp(p, q, dp / (dp - dq), floats);
}

// Sutherland-Hodgman in homogeneous space; returns the vertex count of the clipped polygon (0 if gone).
int clip_polygon(std::array<ClipVertex, 9>& poly, int n, const Planes& planes, int floats) {
  std::array<ClipVertex, 9> out;
  for (int plane = 0; plane < kPlaneCount && n >= 3; ++plane) {
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const ClipVertex& a = poly[i];
      const ClipVertex& b = poly[(i + 1) % n];
      const bool a_in = planes.distance(a, plane) >= 0, b_in = planes.distance(b, plane) >= 0;
      if (a_in) out[m++] = a;
      if (a_in != b_in) out[m++] = intersect(a, b, plane, planes, floats);
    }
    poly = out;
    n = m;
  }
  return n >= 3 ? n : 0;
}

// The same for a segment (parametric): false when nothing is left.
bool clip_segment(ClipVertex& a, ClipVertex& b, const Planes& planes, int floats) {
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    const double da = planes.distance(a, plane), db = planes.distance(b, plane);
    if (da < 0 && db < 0) return false;
    if (da < 0)
      a = intersect(a, b, plane, planes, floats);
    else if (db < 0)
      b = intersect(a, b, plane, planes, floats);
  }
  return true;
}

struct Viewport {
  double width, height;
  // Perspective divide and viewport: NDC x right, y up -> pixels x right, y down.
  void project(const ClipVertex& v, double& sx, double& sy, double& depth, double& inv_w) const {
    inv_w = 1.0 / v.w;  // clipping guarantees w > 0
    sx = (v.x * inv_w + 1) * 0.5 * width;
    sy = (1 - v.y * inv_w) * 0.5 * height;
    depth = std::clamp(v.z * inv_w, 0.0, 1.0);
  }
};

// Clipping keeps every vertex inside the guard band in exact arithmetic. In doubles, coordinates near 1e30
// cancel catastrophically and a clipped vertex can land anywhere, even at w = 0 (found by the fuzzer: a
// NaN reached an integer conversion). Such a vertex has no trustworthy position: its primitive is dropped.
bool in_guard_band(double sx, double sy, double inv_w) {
  return std::isfinite(inv_w) && inv_w > 0 && std::fabs(sx) <= kFastRangePx && std::fabs(sy) <= kFastRangePx;
}

Rgba8 to_rgba8(const float* c) {
  return {to_byte(c[0]), to_byte(c[1]), to_byte(c[2]), to_byte(c[3])};
}

void put_color(float* to, Rgba8 c) {
  to[0] = c.r, to[1] = c.g, to[2] = c.b, to[3] = c.a;
}

/// Where the viewport puts a projected vertex's depth and 1 / w, for the rows `varyings` has.
void put_projection(const VaryingLayout& varyings, SetupVertex& v, double depth, double inv_w) {
  if (varyings.has(Varying::depth)) *v.at(varyings, Varying::depth) = static_cast<float>(depth);
  if (varyings.has(Varying::inv_w)) *v.at(varyings, Varying::inv_w) = static_cast<float>(inv_w);
}

/// A vertex inside every clip plane, projected: what its triangles' records are made of.
struct ScreenVertex {
  std::int32_t x, y;  ///< snapped, 1/256 px, origin top-left, y down (inside the guard band: |x| < 2^23)
  float depth;        ///< z / w in [0, 1], reversed
  float inv_w;        ///< 1 / w
};

/// Meshes with at least twice this many vertices (triangles) have them transformed (set up, and their
/// normals computed) on every render thread: vertices in pieces of this size, triangles in four pieces a
/// thread of at least this size. Smaller ones stay on the calling thread. 1024: the Stanford bunny (3,674
/// triangles) renders 6% faster at 2 threads split than whole (1.33-1.35 against 1.42 ms, plan + render);
/// a hand-off costs far less than a thousand triangles' setup.
constexpr std::size_t kPiece = 1024;

/// A mesh through the camera: every vertex once (which clip planes it is outside of, its world position,
/// and inside all of them its projected, snapped screen position, so a triangle that needs no clipping
/// costs no projection), and what the triangles and lines share.
struct MeshView {
  const Mesh& mesh;
  const RenderPlan& plan;
  Planes planes;
  Viewport viewport;
  Mat4 model_to_clip;
  // Per vertex, each written once before it is read:
  PodArray<std::uint8_t>
      outside;  ///< bit p: outside plane p; 0x40: inside but not projectable; 0x80: not finite
  PodArray<ScreenVertex> screen;  ///< valid where outside == 0
  PodArray<Vec3> world;           ///< world positions

  MeshView(const Mesh& m, const RenderPlan& p)
      : mesh(m),
        plan(p),
        planes{1 + 2 * kGuardPx / p.width, 1 + 2 * kGuardPx / p.height},
        viewport{static_cast<double>(p.width), static_cast<double>(p.height)},
        model_to_clip(p.view.world_to_clip * m.transform) {
    outside.resize_uninitialized(m.positions.size()), screen.resize_uninitialized(m.positions.size()),
        world.resize_uninitialized(m.positions.size());
  }

  /// Every vertex, in pieces on the render's threads (each writes its own vertices). False when stopped.
  bool project(StopMeter& meter) {
    const std::size_t nv = mesh.positions.size();
    const std::size_t pieces = (nv + kPiece - 1) / kPiece;
    parallel_for(nv >= 2 * kPiece ? plan.threads : 1, pieces, meter.stop(),
                 [&](std::size_t piece, StopMeter& own, int) {
                   const std::size_t end = std::min(nv, (piece + 1) * kPiece);
                   for (std::size_t i = piece * kPiece; i < end; ++i) {
                     if (own.add(StopMeter::kRowWork)) return;  // a model can have millions of vertices
                     project_vertex(i);
                   }
                 });
    return !meter.check();
  }

  void project_vertex(std::size_t i) {
    world[i] = transform_point(mesh.transform, mesh.positions[i]);
    const Vec4 c = transform(model_to_clip, mesh.positions[i]);
    if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w))) {
      outside[i] = 0x80;
      return;
    }
    const ClipVertex v{c.x, c.y, c.z, c.w, {}};
    std::uint8_t bits = 0;
    for (int plane = 0; plane < kPlaneCount; ++plane)
      bits |= (planes.distance(v, plane) < 0 ? 1 : 0) << plane;
    outside[i] = bits;
    if (bits) return;
    double sx, sy, depth, inv_w;
    viewport.project(v, sx, sy, depth, inv_w);
    if (!in_guard_band(sx, sy, inv_w)) {
      outside[i] = 0x40;  // inside every plane yet not projectable: dropped like a clipped one would be
      return;
    }
    screen[i] = {static_cast<std::int32_t>(snap(sx)), static_cast<std::int32_t>(snap(sy)),
                 static_cast<float>(depth), static_cast<float>(inv_w)};
  }

  Rgba8 vertex_color(std::uint32_t vertex) const {
    return mesh.colors.size() == 1 ? mesh.colors[0] : mesh.colors[vertex];
  }
  Rgba8 color_at(std::size_t triangle, std::uint32_t vertex) const {
    return mesh.face_colors.empty() ? vertex_color(vertex) : mesh.face_colors[triangle];
  }
  /// The vertex in clip space (computed again: only clipped primitives need it), with colour `c` in the
  /// place `varyings` gives it.
  ClipVertex clip_vertex(std::uint32_t i, const VaryingLayout& varyings, Rgba8 c) const {
    const Vec4 p = transform(model_to_clip, mesh.positions[i]);
    ClipVertex v{p.x, p.y, p.z, p.w, {}};
    put_color(v.values + varyings.vertex_offset[static_cast<int>(Varying::color)], c);
    return v;
  }
};

// A triangle that crosses a clip plane: clipped in homogeneous space, projected, fanned into records.
void add_clipped(const MeshView& view, std::array<ClipVertex, 9>& poly, std::uint32_t call, bool back,
                 const Setup& setup, Records& part) {
  const VaryingLayout& varyings = setup.calls[call].layout;
  SetupVertex dv[9];
  const int n = clip_polygon(poly, 3, view.planes, varyings.clipped_floats);
  for (int k = 0; k < n; ++k) {
    double sx, sy, depth, inv_w;
    view.viewport.project(poly[k], sx, sy, depth, inv_w);
    if (!in_guard_band(sx, sy, inv_w)) return;
    dv[k].x = snap(sx), dv[k].y = snap(sy);
    std::copy_n(poly[k].values, varyings.clipped_floats, dv[k].values);
    put_projection(varyings, dv[k], depth, inv_w);
  }
  for (int k = 1; k + 1 < n; ++k) setup.add_triangle(part, call, {dv[0], dv[k], dv[k + 1]}, back);
}

/// What the triangles of one mesh share while they are set up, piece by piece.
struct TriangleJob {
  const MeshView& view;
  const PrimitivePlan& mode;
  const Setup& setup;
  std::uint32_t call;                        ///< faces without a texture (or untextured meshes)
  std::vector<std::uint32_t> texture_calls;  ///< textured: the call of each of the mesh's textures
  PodArray<Vec3> normals;  ///< per-pixel lighting: world space, per position (computed) or per OBJ normal
  Vec3 forward;            ///< unit view direction
  MaterialCalls material_calls;  ///< specular meshes: the call of each (texture, material) pair

  // Triangles [begin, end) into `part`, in order.
  void run(std::size_t begin, std::size_t end, Records& part, StopMeter& meter) const;
  // What the shading of triangle `t` interpolates, per vertex: colours (lit per face when flat), normals,
  // texture coordinates, world positions. Returns the triangle's draw call (its texture's, when textured).
  // `face`: its counter-clockwise world normal; `back`: seen from behind.
  [[gnu::always_inline]] inline std::uint32_t vertices(std::size_t t, const Vec3& face, bool back,
                                                       SetupVertex (&dv)[3]) const;
};

std::uint32_t TriangleJob::vertices(std::size_t t, const Vec3& face, bool back, SetupVertex (&dv)[3]) const {
  const Mesh& mesh = view.mesh;
  const PodArray<Vec3>& world = view.world;
  const auto& tri = mesh.triangles[t];
  const VaryingLayout& with = setup.calls[call].layout;
  float shade[3] = {1, 1, 1};
  if (mode.lit &&
      !with.has(Varying::normal)) {  // flat: once per face, lit from the side seen, at its centroid
    const Vec3 n = normalize(back ? face * -1.0 : face);
    const Vec3 c = (world[tri[0]] + world[tri[1]] + world[tri[2]]) * (1.0 / 3);
    const float normal[3] = {static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z)};
    const float centre[3] = {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)};
    light_lanes<3>(setup.calls[call].lights, normal, centre, shade);
  }
  std::uint32_t triangle_call = call;
  std::int32_t texture = -1;
  if (with.has(Varying::uv)) {
    texture = mesh.face_textures.empty() ? 0 : mesh.face_textures[t];
    if (texture >= 0) triangle_call = texture_calls[static_cast<std::size_t>(texture)];
    for (int k = 0; k < 3; ++k) {
      const auto& uv = mesh.uvs[mesh.uv_triangles[t][k]];
      float* to = dv[k].at(with, Varying::uv);
      to[0] = uv[0], to[1] = uv[1];
    }
  }
  for (int k = 0; k < 3; ++k) {
    const Rgba8 c = view.color_at(t, tri[k]);
    float* color = dv[k].at(with, Varying::color);
    color[0] = c.r * shade[0], color[1] = c.g * shade[1], color[2] = c.b * shade[2], color[3] = c.a;
    auto put = [&](Varying name, const Vec3& v) {
      float* to = dv[k].at(with, name);
      to[0] = static_cast<float>(v.x), to[1] = static_cast<float>(v.y), to[2] = static_cast<float>(v.z);
    };
    if (mode.face_normals)  // flat specular: the face's own normal at each corner (flipped when shaded)
      put(Varying::normal, normalize(face));
    else if (with.has(Varying::normal))
      put(Varying::normal,
          mesh.normal_triangles.empty() ? normals[tri[k]] : normals[mesh.normal_triangles[t][k]]);
    if (with.has(Varying::position)) put(Varying::position, world[tri[k]]);
  }
  if (mode.specular) triangle_call = material_calls.at(material_key(mesh, t, texture));
  return triangle_call;
}

void TriangleJob::run(std::size_t begin, std::size_t end, Records& part, StopMeter& meter) const {
  const Mesh& mesh = view.mesh;
  const ViewPlan& camera = view.plan.view;
  const PodArray<Vec3>& world = view.world;
  const VaryingLayout& with = setup.calls[call].layout;
  const std::size_t floats = static_cast<std::size_t>(with.record_floats());
  part.triangles.reserve_more(end - begin), part.order.reserve_more(end - begin);
  part.attributes.reserve_more((end - begin) * floats);
  for (std::size_t t = begin; t < end; ++t) {
    if (meter.add(StopMeter::kPrimitiveWork)) return;  // deadline: a mesh can be millions of triangles
    const auto& tri = mesh.triangles[t];
    // A user matrix can overflow doubles (1e300 x 1e30): such a vertex has no position, and clipping
    // arithmetic on inf/NaN would produce NaN coordinates. The triangle is dropped.
    const std::uint8_t any_out = view.outside[tri[0]] | view.outside[tri[1]] | view.outside[tri[2]];
    if (any_out & 0xc0) continue;
    if (view.outside[tri[0]] & view.outside[tri[1]] & view.outside[tri[2]]) continue;  // beyond one plane

    // Inside every plane, the record first: most of a dense mesh's triangles cover no pixel centre and are
    // dropped before their world positions (or any attribute) are looked at.
    int order[3] = {0, 1, 2};
    if (any_out == 0) {  // the record is made where it will stay
      FastTriangle fast;
      for (int k = 0; k < 3; ++k) fast.x[k] = view.screen[tri[k]].x, fast.y[k] = view.screen[tri[k]].y;
      if (!setup.fast_record(fast, part.grow_triangle(), order)) {
        part.drop_triangle();
        continue;
      }
    }
    // Facing from world geometry (valid on both sides of the eye, unlike a post-divide winding test):
    // front when the counter-clockwise normal points toward the eye.
    const Vec3 face = cross(world[tri[1]] - world[tri[0]], world[tri[2]] - world[tri[0]]);
    const Vec3 toward_eye =
        camera.projection == Projection::perspective ? camera.eye - world[tri[0]] : forward * -1.0;
    const bool back = dot(face, toward_eye) < 0;
    if (back && mesh.cull == Cull::back) {
      if (any_out == 0) part.drop_triangle();
      continue;
    }

    // The vertices' colours (lit per face) and normals, onto the projected vertices or the clip polygon.
    SetupVertex dv[3];
    const std::uint32_t triangle_call = vertices(t, face, back, dv);
    if (any_out == 0) {  // inside every plane: the vertices were projected once
      for (int k = 0; k < 3; ++k)
        put_projection(with, dv[k], view.screen[tri[k]].depth, view.screen[tri[k]].inv_w);
      setup.finish(part, triangle_call, {&dv[order[0]], &dv[order[1]], &dv[order[2]]}, back);
      continue;
    }
    std::array<ClipVertex, 9> poly;
    for (int k = 0; k < 3; ++k) {
      poly[k] = view.clip_vertex(tri[k], with, {});
      std::copy_n(dv[k].values, with.clipped_floats, poly[k].values);
    }
    add_clipped(view, poly, triangle_call, back, setup, part);
  }
}

// The mesh's triangles into records: in pieces of kPiece triangles on every render thread, each piece
// into a part of its own (parts in triangle order, so the image is that of one thread).
void add_triangles(const MeshView& view, const PrimitivePlan& mode, Setup& setup, StopMeter& meter) {
  const Mesh& mesh = view.mesh;
  const ViewPlan& camera = view.plan.view;
  TriangleJob job{view, mode, setup, 0, {}, {}, normalize(camera.target - camera.eye), {}};
  if (mode.varyings.has(Varying::normal)) {
    const Mat4 to_world_normal = normal_matrix(mesh.transform);
    if (mode.compute_normals)
      job.normals =
          vertex_normals(mesh, std::span<const Vec3>(view.world.data(), view.world.size()),
                         mesh.triangles.size() >= 2 * kPiece ? view.plan.threads : 1, view.plan.simd, meter);
    else
      for (const Vec3 n : mesh.normals) job.normals.push_back(normalize(transform_point(to_world_normal, n)));
    if (meter.stopped()) return;
  }
  DrawCall call = make_call(mode);
  if (mode.lit) call.lights = LightRig::of(camera.lights);
  job.call = setup.add_call(call);
  // Textured: one call per texture, the same mode; faces without a texture keep `job.call` (no texture).
  std::vector<const MipChain*> chains;
  if (mode.varyings.has(Varying::uv))
    for (const Texture& texture : mesh.textures) {
      call.texture = &setup.textures.emplace_back(build_mips(texture, &meter));
      if (meter.stopped()) return;
      chains.push_back(call.texture);
      job.texture_calls.push_back(setup.add_call(call));
    }
  if (mode.specular)
    job.material_calls =
        add_material_calls(mesh, view.plan.view, mode.varyings.has(Varying::uv), chains, call, setup);
  in_parts(mesh.triangles.size(), kPiece, view.plan.threads, setup, meter,
           [&](std::size_t begin, std::size_t end, Records& part, StopMeter& own) {
             job.run(begin, end, part, own);
           });
}

// A projected segment as the rectangle `width` pixels wide around it (butt caps), two triangles whose depth
// and 1/w are the endpoints' across the width: how multisampling draws 3D lines, and how wide edges are
// drawn.
void add_line_rectangle(const ClipVertex& a, const ClipVertex& b, double ax, double ay, double ad, double aw,
                        double bx, double by, double bd, double bw, double width, std::uint32_t call,
                        Setup& setup) {
  const VaryingLayout& with = setup.calls[call].layout;
  const double dx = bx - ax, dy = by - ay, len = std::hypot(dx, dy);
  if (!(len > 0)) return;
  const double nx = -dy / len * 0.5 * width, ny = dx / len * 0.5 * width;
  SetupVertex q[4];
  const double px[4] = {ax + nx, bx + nx, bx - nx, ax - nx}, py[4] = {ay + ny, by + ny, by - ny, ay - ny};
  for (int k = 0; k < 4; ++k) {
    const bool at_a = k == 0 || k == 3;
    q[k].x = snap(px[k]), q[k].y = snap(py[k]);
    std::copy_n((at_a ? a : b).values, with.clipped_floats, q[k].values);
    put_projection(with, q[k], at_a ? ad : bd, at_a ? aw : bw);
  }
  setup.add_triangle(call, {q[0], q[1], q[2]});
  setup.add_triangle(call, {q[0], q[2], q[3]});
}

// One 3D segment through clipping and projection: a line record, or with `mode.line_rectangles` the
// rectangle `width` pixels wide around it.
void add_segment(const MeshView& view, ClipVertex a, ClipVertex b, const PrimitivePlan& mode,
                 std::uint32_t call, double width, Setup& setup) {
  const VaryingLayout& with = setup.calls[call].layout;
  if (!clip_segment(a, b, view.planes, with.clipped_floats)) return;
  double ax, ay, ad, aw, bx, by, bd, bw;
  view.viewport.project(a, ax, ay, ad, aw);
  view.viewport.project(b, bx, by, bd, bw);
  if (!in_guard_band(ax, ay, aw) || !in_guard_band(bx, by, bw)) return;
  if (mode.line_rectangles) {
    add_line_rectangle(a, b, ax, ay, ad, aw, bx, by, bd, bw, width, call, setup);
    return;
  }
  LineRecord line;
  line.x0 = std::floor(ax), line.y0 = std::floor(ay), line.x1 = std::floor(bx), line.y1 = std::floor(by);
  const int color = with.vertex_offset[static_cast<int>(Varying::color)];
  line.c0 = to_rgba8(a.values + color), line.c1 = to_rgba8(b.values + color);
  line.depth0 = static_cast<float>(ad), line.depth1 = static_cast<float>(bd);
  line.call = call;
  setup.add_line(line);
}

// Lines: the mesh's own segments, and for wireframes every triangle edge once.
void add_lines(const MeshView& view, const PrimitivePlan& line_mode, Setup& setup, StopMeter& meter) {
  const Mesh& mesh = view.mesh;
  std::vector<std::array<std::uint32_t, 2>> segments = mesh.segments;
  std::vector<std::array<Rgba8, 2>> segment_colors;
  for (const auto& s : mesh.segments)
    segment_colors.push_back({view.vertex_color(s[0]), view.vertex_color(s[1])});
  if (mesh.wireframe) {
    std::vector<std::tuple<std::uint32_t, std::uint32_t, std::size_t>> edges;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (meter.add(StopMeter::kPrimitiveWork)) return;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
        edges.emplace_back(std::min(a, b), std::max(a, b), t);
      }
    }
    std::sort(edges.begin(), edges.end());  // not interruptible: n log n of the model's edges
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const auto [a, b, t] = edges[i];
      if (i > 0 && std::get<0>(edges[i - 1]) == a && std::get<1>(edges[i - 1]) == b) continue;
      segments.push_back({a, b});
      segment_colors.push_back({view.color_at(t, a), view.color_at(t, b)});
    }
  }
  if (segments.empty()) return;
  const std::uint32_t line_call = setup.add_call(make_call(line_mode));
  for (std::size_t s = 0; s < segments.size(); ++s) {
    if (meter.add(StopMeter::kPrimitiveWork)) break;
    if ((view.outside[segments[s][0]] | view.outside[segments[s][1]]) & 0x80) continue;
    const VaryingLayout& with = setup.calls[line_call].layout;
    add_segment(view, view.clip_vertex(segments[s][0], with, segment_colors[s][0]),
                view.clip_vertex(segments[s][1], with, segment_colors[s][1]), line_mode, line_call, 1, setup);
  }
}

// Feature edges (scene.h: Edges): each edge of the triangles once, kept when it bounds one face, is shared by
// more than two, or its two faces' normals differ by more than the crease angle; drawn in the edge colour
// with its endpoints moved toward the eye by two pixels' worth of distance (a polygon offset), so the faces
// they lie on, whose depth at a pixel differs from the line's by up to their slope, do not half-hide them.
void add_edges(const MeshView& view, const PrimitivePlan& edge_mode, Setup& setup, StopMeter& meter) {
  const Mesh& mesh = view.mesh;
  const ViewPlan& camera = view.plan.view;
  const std::span<const Vec3> world = std::span<const Vec3>(view.world.data(), view.world.size());
  // Positions with equal coordinates are one point here: models that repeat a corner per face (UV seams,
  // STL-like soups) still have shared edges, not a boundary around every face.
  std::vector<std::uint32_t> same(world.size());
  {
    std::vector<std::uint32_t> order(world.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    auto key = [&](std::uint32_t i) { return std::tuple(world[i].x, world[i].y, world[i].z); };
    std::sort(order.begin(), order.end(), [&](std::uint32_t p, std::uint32_t q) { return key(p) < key(q); });
    for (std::size_t k = 0; k < order.size(); ++k)
      same[order[k]] = k > 0 && key(order[k]) == key(order[k - 1]) ? same[order[k - 1]] : order[k];
  }
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> edges;  // (low, high, triangle)
  edges.reserve(mesh.triangles.size() * 3);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (meter.add(StopMeter::kPrimitiveWork)) return;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = same[mesh.triangles[t][k]], b = same[mesh.triangles[t][(k + 1) % 3]];
      if (a != b) edges.emplace_back(std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(t));
    }
  }
  std::sort(edges.begin(), edges.end());  // not interruptible: n log n of the model's edges
  auto face_normal = [&](std::uint32_t t) {
    const auto& tri = mesh.triangles[t];
    return normalize(cross(world[tri[1]] - world[tri[0]], world[tri[2]] - world[tri[0]]));
  };
  const double cos_crease = std::cos(mesh.edges.crease_deg * std::numbers::pi / 180);
  const Vec3 forward = normalize(camera.target - camera.eye);
  const double pixel_at_unit =
      (camera.projection == Projection::perspective ? 2 * std::tan(camera.fov_deg * std::numbers::pi / 360)
                                                    : 0) /
      view.plan.height;
  const double ortho_pixel = camera.height / view.plan.height;
  // The endpoint in clip space, with the depth it would have two pixels nearer the eye: moving it along its
  // ray to the eye leaves it where it is on screen and changes only z. The depth stops at the near plane: on
  // a small image two pixels are more than the 1% margin a fitted near plane leaves in front of the content,
  // and edges on its nearest face would be clipped away.
  const VaryingLayout edge_layout = VaryingLayout::of(edge_mode.varyings);
  auto pulled = [&](std::uint32_t i) {
    const Vec3& p = world[i];
    Vec3 toward_eye = forward * -1.0;
    double pixel = ortho_pixel;
    if (camera.projection == Projection::perspective) {
      const double d = length(camera.eye - p);
      toward_eye = normalize(camera.eye - p), pixel = d * pixel_at_unit;
    }
    const Vec4 c = transform(camera.world_to_clip, p);
    const Vec4 nearer = transform(camera.world_to_clip, p + toward_eye * (2 * pixel));
    double z = c.z;  // reversed depth: z = w at the near plane, larger z / w is nearer
    if (c.w > 0 && nearer.w > 0) z = std::max(z, std::min(nearer.z / nearer.w, 1.0) * c.w);
    ClipVertex v{c.x, c.y, z, c.w, {}};
    put_color(v.values + edge_layout.vertex_offset[static_cast<int>(Varying::color)], mesh.edges.color);
    return v;
  };
  const std::uint32_t call = setup.add_call(make_call(edge_mode));
  for (std::size_t i = 0; i < edges.size();) {
    if (meter.add(StopMeter::kPrimitiveWork)) return;
    const auto [a, b, t] = edges[i];
    std::size_t j = i + 1;
    while (j < edges.size() && std::get<0>(edges[j]) == a && std::get<1>(edges[j]) == b) ++j;
    const std::size_t faces = j - i;
    bool feature = faces != 2;
    if (faces == 2) {
      const Vec3 n0 = face_normal(t), n1 = face_normal(std::get<2>(edges[i + 1]));
      // A degenerate face has no normal (NaN): its edges are not creases of it.
      feature = dot(n0, n1) < cos_crease;
    }
    i = j;
    if (!feature || ((view.outside[a] | view.outside[b]) & 0x80)) continue;
    ClipVertex va = pulled(a), vb = pulled(b);
    if (!(std::isfinite(va.w) && std::isfinite(vb.w))) continue;
    add_segment(view, va, vb, edge_mode, call, mesh.edges.width, setup);
  }
}

// Points (scene.h: Mesh::points): a record each, a disc at the projected vertex. One beyond the near or far
// plane or the guard band (which a disc of <= 64 px cannot cross into the image) is dropped whole.
void add_points(const MeshView& view, const PrimitivePlan& point_mode, Setup& setup, StopMeter& meter) {
  const Mesh& mesh = view.mesh;
  const std::uint32_t call = setup.add_call(make_call(point_mode));
  // The radius in whole 1/256 px (coverage is decided in integers).
  const std::int64_t radius = std::llround(static_cast<double>(mesh.point_size) * (kSubpixelScale / 2.0));
  in_parts(mesh.points.size(), kPiece, view.plan.threads, setup, meter,
           [&](std::size_t begin, std::size_t end, Records& part, StopMeter& own) {
             part.points.reserve_more(end - begin), part.order.reserve_more(end - begin);
             for (std::size_t k = begin; k < end; ++k) {
               if (own.add(StopMeter::kRowWork)) return;  // deadline: a cloud can be millions of points
               const std::uint32_t i = mesh.points[k];
               if (view.outside[i]) continue;
               const ScreenVertex& v = view.screen[i];
               setup.add_point(part, {v.x, v.y, radius, v.depth, view.vertex_color(i), call, {}});
             }
           });
}

}  // namespace

void add_mesh(const Mesh& mesh, const DrawPlan& draw, const RenderPlan& plan, Setup& setup,
              StopMeter& meter) {
  MeshView view(mesh, plan);
  if (!view.project(meter)) return;
  if (!mesh.wireframe && !mesh.triangles.empty()) add_triangles(view, draw.mode, setup, meter);
  add_lines(view, draw.line_mode, setup, meter);
  if (draw.edge_mode.depth) add_edges(view, draw.edge_mode, setup, meter);
  if (draw.point_mode.depth) add_points(view, draw.point_mode, setup, meter);
}

}  // namespace raster::detail
