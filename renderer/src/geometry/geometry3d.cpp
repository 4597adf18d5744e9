// Geometry for 3D content: model -> world -> clip space, lighting of flat faces, homogeneous clipping,
// perspective divide, viewport and snapping. Produces the same triangle records the 2D path does. The
// mesh's lines, edges and points are geometry3d_lines.cpp's; what both use is geometry/mesh_view.h.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <span>

#include "geometry/mesh_view.h"
#include "geometry/normals.h"
#include "plan/light.h"

namespace raster::detail {
namespace {

using namespace mesh3d;

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
  CornerNormals creases;   ///< computed normals of a creased mesh: the corners split from their vertex's
  Vec3 forward;            ///< unit view direction
  MaterialCalls material_calls;  ///< specular meshes: the call of each (texture, material) pair
  /// A dense mesh's triangles that may draw, found before its normals (mark()): bit t % 8 of byte t / 8, and
  /// a spare byte. Empty otherwise: run() then asks candidates() itself.
  PodArray<std::uint8_t> kept;

  // Triangles [begin, end) into `part`, in order.
  void run(std::size_t begin, std::size_t end, Records& part, StopMeter& meter) const;
  // Triangle t into `part`, when it draws anything.
  void triangle(std::size_t t, Records& part) const;
  // Every triangle of [begin, end) (begin a multiple of 8) that triangle() could keep, into `kept`, and its
  // corners marked in `needed` (a byte a vertex, set to 1 by any thread): the same decisions as triangle()
  // makes, without a record kept.
  void mark(std::size_t begin, std::size_t end, std::uint8_t* needed, StopMeter& meter);

  // The triangles of the 8 from `first` (n of them) that may cover a sample, as bits (setup/batch.h): with
  // centre coverage or multisampling, whose sample positions are known here; else all n.
  std::uint32_t candidates(std::size_t first, int n) const;
  // The planes some corner of `tri` is outside of (0: inside every one, its corners projected), or -1 when
  // it draws nothing: beyond one plane, or a corner without a position (a user matrix can overflow doubles,
  // 1e300 x 1e30, and clipping arithmetic on inf/NaN would make NaN coordinates).
  int outside_of(const std::array<std::uint32_t, 3>& tri) const;
  // Inside every plane: the record from the projected corners, into `r`; false when it covers no sample.
  bool fast(const std::array<std::uint32_t, 3>& tri, TriangleRecord& r, int (&order)[3]) const;
  // The counter-clockwise world normal of `tri`, and whether it faces away from the eye (from world
  // geometry, valid on both sides of the eye, unlike a post-divide winding test).
  bool back_facing(const std::array<std::uint32_t, 3>& tri, Vec3& face) const;
  // What the shading of triangle `t` interpolates, per vertex: colours (lit per face when flat), normals,
  // texture coordinates, world positions. Returns the triangle's draw call (its texture's, when textured).
  // `face`: its counter-clockwise world normal; `back`: seen from behind.
  [[gnu::always_inline]] inline std::uint32_t vertices(std::size_t t, const Vec3& face, bool back,
                                                       SetupVertex (&dv)[3]) const;
};

std::uint32_t TriangleJob::vertices(std::size_t t, const Vec3& face, bool back, SetupVertex (&dv)[3]) const {
  const Mesh& mesh = view.mesh;
  const auto& tri = mesh.triangles[t];
  const VaryingLayout& with = setup.calls[call].layout;
  float shade[3] = {1, 1, 1};
  if (mode.lit &&
      !with.has(Varying::normal)) {  // flat: once per face, lit from the side seen, at its centroid
    const Vec3 n = normalize(back ? face * -1.0 : face);
    const Vec3 c = (view.world_at(tri[0]) + view.world_at(tri[1]) + view.world_at(tri[2])) * (1.0 / 3);
    light_face(setup.calls[call].lights, n, c, shade);
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
    else if (with.has(Varying::normal)) {
      const Vec3f* split = creases.empty() ? nullptr : creases.at(tri[k], static_cast<std::uint32_t>(t));
      if (split)
        put(Varying::normal, {split->x + 0.0, split->y + 0.0, split->z + 0.0});
      else
        put(Varying::normal,
            mesh.normal_triangles.empty() ? normals[tri[k]] : normals[mesh.normal_triangles[t][k]]);
    }
    if (with.has(Varying::position)) put(Varying::position, view.world_at(tri[k]));
  }
  if (mode.specular) triangle_call = material_calls.at(material_key(mesh, t, texture));
  return triangle_call;
}

std::uint32_t TriangleJob::candidates(std::size_t first, int n) const {
  static constexpr SamplePoint kCentre{};
  if (!setup.centre_samples && !setup.pattern) return (1u << n) - 1;
  return sample_candidates(
      &view.mesh.triangles[first], n, view.screen.data(), setup.centre_samples ? &kCentre : setup.pattern,
      setup.centre_samples ? 1 : setup.pattern_size, view.plan.width, view.plan.height, view.plan.simd);
}

int TriangleJob::outside_of(const std::array<std::uint32_t, 3>& tri) const {
  const std::uint8_t any_out = view.outside[tri[0]] | view.outside[tri[1]] | view.outside[tri[2]];
  if (any_out & 0xc0) return -1;
  if (view.outside[tri[0]] & view.outside[tri[1]] & view.outside[tri[2]]) return -1;
  return any_out;
}

bool TriangleJob::fast(const std::array<std::uint32_t, 3>& tri, TriangleRecord& r, int (&order)[3]) const {
  FastTriangle f;
  for (int k = 0; k < 3; ++k) f.x[k] = view.screen[tri[k]].x, f.y[k] = view.screen[tri[k]].y;
  return setup.fast_record(f, r, order);
}

bool TriangleJob::back_facing(const std::array<std::uint32_t, 3>& tri, Vec3& face) const {
  const ViewPlan& camera = view.plan.view;
  const Vec3 a = view.world_at(tri[0]);
  face = cross(view.world_at(tri[1]) - a, view.world_at(tri[2]) - a);
  const Vec3 toward_eye = camera.projection == Projection::perspective ? camera.eye - a : forward * -1.0;
  return dot(face, toward_eye) < 0;
}

void TriangleJob::run(std::size_t begin, std::size_t end, Records& part, StopMeter& meter) const {
  const VaryingLayout& with = setup.calls[call].layout;
  const std::size_t floats = static_cast<std::size_t>(with.record_floats());
  part.triangles.reserve_more(end - begin), part.order.reserve_more(end - begin);
  part.attributes.reserve_more((end - begin) * floats);
  // The records are asked of the budget as they are made (Records::account): most triangles make none.
  std::int64_t asked = part.bytes();
  for (std::size_t first = begin; first < end; first += 8) {
    const int n = static_cast<int>(std::min<std::size_t>(8, end - first));
    if (meter.add(n * StopMeter::kPrimitiveWork)) return;  // deadline: a mesh can be millions of triangles
    if (!part.account(meter.stop(), asked)) return;
    std::uint32_t batch;
    if (kept.empty()) {
      batch = candidates(first, n);
    } else {  // the bits of [first, first + n), from the bytes they lie in
      const std::uint32_t window = kept[first / 8] | std::uint32_t{kept[first / 8 + 1]} << 8;
      batch = (window >> (first % 8)) & ((1u << n) - 1);
    }
    for (; batch; batch &= batch - 1) triangle(first + static_cast<std::size_t>(__builtin_ctz(batch)), part);
  }
  part.account(meter.stop(), asked, true);
}

void TriangleJob::mark(std::size_t begin, std::size_t end, std::uint8_t* needed, StopMeter& meter) {
  const Mesh& mesh = view.mesh;
  TriangleRecord scratch;
  for (std::size_t first = begin; first < end; first += 8) {
    const int n = static_cast<int>(std::min<std::size_t>(8, end - first));
    if (meter.add(n * StopMeter::kPrimitiveWork)) return;
    std::uint8_t bits = 0;
    for (std::uint32_t batch = candidates(first, n); batch; batch &= batch - 1) {
      const int i = __builtin_ctz(batch);
      const auto& tri = mesh.triangles[first + static_cast<std::size_t>(i)];
      const int out = outside_of(tri);
      int order[3];
      Vec3 face;
      if (out < 0 || (out == 0 && !fast(tri, scratch, order)) ||
          (mesh.cull == Cull::back && back_facing(tri, face)))
        continue;
      bits |= static_cast<std::uint8_t>(1u << i);
      for (std::uint32_t v : tri)
        std::atomic_ref<std::uint8_t>(needed[v]).store(1, std::memory_order_relaxed);
    }
    kept[first / 8] = bits;
  }
}

void TriangleJob::triangle(std::size_t t, Records& part) const {
  const Mesh& mesh = view.mesh;
  const VaryingLayout& with = setup.calls[call].layout;
  const auto& tri = mesh.triangles[t];
  const int any_out = outside_of(tri);
  if (any_out < 0) return;
  // Inside every plane, the record first: most of a dense mesh's triangles cover no pixel centre and are
  // dropped before their world positions (or any attribute) are looked at.
  int order[3] = {0, 1, 2};
  if (any_out == 0 && !fast(tri, part.grow_triangle(), order)) {  // made where it will stay
    part.drop_triangle();
    return;
  }
  Vec3 face;
  const bool back = back_facing(tri, face);
  if (back && mesh.cull == Cull::back) {
    if (any_out == 0) part.drop_triangle();
    return;
  }

  // The vertices' colours (lit per face) and normals, onto the projected vertices or the clip polygon.
  SetupVertex dv[3];
  const std::uint32_t triangle_call = vertices(t, face, back, dv);
  if (any_out == 0) {  // inside every plane: the vertices were projected once
    for (int k = 0; k < 3; ++k)
      put_projection(with, dv[k], view.screen[tri[k]].depth, view.screen[tri[k]].inv_w);
    setup.finish(part, triangle_call, {&dv[order[0]], &dv[order[1]], &dv[order[2]]}, back);
    return;
  }
  std::array<ClipVertex, 9> poly;
  for (int k = 0; k < 3; ++k) {
    poly[k] = view.clip_vertex(tri[k], with, {});
    std::copy_n(dv[k].values, with.clipped_floats, poly[k].values);
  }
  add_clipped(view, poly, triangle_call, back, setup, part);
}

// The mesh's triangles into records: in pieces of kPiece triangles on every render thread, each piece
// into a part of its own (parts in triangle order, so the image is that of one thread).
void add_triangles(const MeshView& view, const PrimitivePlan& mode, Setup& setup, StopMeter& meter) {
  const Mesh& mesh = view.mesh;
  const ViewPlan& camera = view.plan.view;
  TriangleJob job{view, mode, setup, 0, {}, {}, {}, normalize(camera.target - camera.eye), {}, {}};
  if (mode.varyings.has(Varying::normal)) {
    const Mat4 to_world_normal = normal_matrix(mesh.transform);
    if (mode.compute_normals) {
      const int threads = mesh.triangles.size() >= 2 * kPiece ? view.plan.threads : 1;
      // A mesh of more triangles than pixels draws few of them (a 2M-triangle scan at 512x512: 6%), and only
      // their corners need a normal: the triangles that may draw are found first, in pieces (and kept: run()
      // then makes the records of those alone), and only the faces around their corners are measured.
      PodArray<std::uint8_t> needed;
      if (mode.normals_where_drawn) {
        needed.resize_uninitialized(mesh.positions.size());
        std::fill_n(needed.data(), needed.size(), std::uint8_t{0});
        job.kept.resize_uninitialized(mesh.triangles.size() / 8 + 2);  // a byte for 8, the last's, a spare
        job.kept[job.kept.size() - 2] = job.kept[job.kept.size() - 1] = 0;
        constexpr std::size_t kMarkPiece = 16 * kPiece;
        parallel_for(threads, (mesh.triangles.size() + kMarkPiece - 1) / kMarkPiece, meter.stop(),
                     [&](std::size_t piece, StopMeter& own, int) {
                       job.mark(piece * kMarkPiece, std::min(mesh.triangles.size(), (piece + 1) * kMarkPiece),
                                needed.data(), own);
                     });
        if (meter.check()) return;
      }
      const std::span<const Vec3> world(view.world.data(), view.world.size());
      const std::uint8_t* marked = needed.empty() ? nullptr : needed.data();
      job.normals = vertex_normals(mesh, world, threads, view.plan.simd, meter, marked);
      if (!meter.stopped()) job.creases = crease_normals(mesh, world, job.normals, threads, meter, marked);
    } else
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

}  // namespace

void add_mesh(const Mesh& mesh, const DrawPlan& draw, const RenderPlan& plan, Setup& setup,
              StopMeter& meter) {
  MeshView view(mesh, plan);
  if (!view.project(meter)) return;
  if (!mesh.wireframe && !mesh.triangles.empty()) add_triangles(view, draw.mode, setup, meter);
  // Lines and edges go into the last part, one after another: their records asked for once made.
  std::int64_t asked = setup.last_part().bytes();
  add_lines(view, draw.line_mode, setup, meter);
  if (draw.edge_mode.depth) add_edges(view, draw.edge_mode, setup, meter);
  if (!setup.last_part().account(meter.stop(), asked, true)) return;
  if (draw.point_mode.depth) add_points(view, draw.point_mode, setup, meter);
}

}  // namespace raster::detail
