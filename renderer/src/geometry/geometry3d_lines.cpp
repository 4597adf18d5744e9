// The 3D geometry of a mesh's lines: its segments and wireframe edges, its feature edges (pulled toward the
// eye) and its points, through the camera (geometry/mesh_view.h) into line, rectangle and point records.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <tuple>
#include <vector>

#include "geometry/mesh_view.h"

namespace raster::detail::mesh3d {
namespace {

// A projected segment as the rectangle `width` pixels wide around it (butt caps), two triangles whose depth
// and 1/w are the endpoints' across the width: how multisampling draws 3D lines, and how wide edges are
// drawn.
void add_line_rectangle(const ClipVertex& a, const ClipVertex& b, double ax, double ay, double ad, double aw,
                        double bx, double by, double bd, double bw, double width, std::uint32_t call,
                        Setup& setup) {
  const VaryingLayout& with = setup.calls[call].layout;
  double px[4], py[4];
  if (!segment_rectangle(ax, ay, bx, by, width, px, py)) return;
  SetupVertex q[4];
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

}  // namespace

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
  const std::size_t vertices = mesh.positions.size();
  // Positions with equal coordinates are one point here: models that repeat a corner per face (UV seams,
  // STL-like soups) still have shared edges, not a boundary around every face.
  std::vector<std::uint32_t> same(vertices);
  {
    std::vector<std::uint32_t> order(vertices);
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    auto key = [&](std::uint32_t i) {
      return std::tuple(view.world_at(i).x, view.world_at(i).y, view.world_at(i).z);
    };
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
    const Vec3 a = view.world_at(tri[0]);
    return normalize(cross(view.world_at(tri[1]) - a, view.world_at(tri[2]) - a));
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
    const Vec3 p = view.world_at(i);
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
             std::int64_t asked = part.bytes();  // the records asked for as they are made
             for (std::size_t k = begin; k < end; ++k) {
               if (own.add(StopMeter::kRowWork)) return;  // deadline: a cloud can be millions of points
               if ((k & 1023) == 0 && !part.account(own.stop(), asked)) return;
               const std::uint32_t i = mesh.points[k];
               if (view.outside[i]) continue;
               const ScreenVertex& v = view.screen[i];
               setup.add_point(part, {v.x, v.y, radius, v.depth, view.vertex_color(i), call, {}});
             }
             part.account(own.stop(), asked, true);
           });
}

}  // namespace raster::detail::mesh3d
