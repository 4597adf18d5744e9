// The plan stage: every "does this scene need X" decision, made once, from the scene alone.
#include "raster/plan.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

#include <nlohmann/json.hpp>

#include "base/budget_ask.h"
#include "shade/texture.h"
#include "base/vecmath.h"

namespace raster {
namespace {

// Below this much estimated work (bounding-box pixels touched by visible primitives; clearing is not
// split, so it does not count) a render stays on the calling thread. bench/parallel_threshold measured, with
// v0.1's bands, two threads 1.30x slower at 5.6e4 and 0.82x at 1.1e5 (crossover ~8.5e4). With tiles the same
// benchmark now shows two threads at about parity up to ~5e5 (docs/performance.md): not re-tuned yet.
constexpr std::int64_t kParallelWorkThreshold = 100'000;
// Small scenes never leave the calling thread, whatever their estimate: no hand-off for a thumbnail.
constexpr std::int64_t kSmallScenePixels = 256 * 256;
constexpr std::size_t kSmallScenePrimitives = 100;
// Tile side for images larger than a thumbnail (bench/core measures 32, 64 and 128; see
// docs/performance.md): 128 was 3-10% faster than 64 on every scene there, at 1 and 2 threads, aliased.
// Multisampling keeps 64: a tile's sample planes (up to 16 colours a pixel) stay in the cache.
constexpr int kTile = 128;
constexpr int kSampleTile = 64;
// "antialias": "area" on a scene with 3D content: multisampling at this many samples (docs/accuracy.md).
constexpr Antialias kAreaFallback3d = Antialias::msaa8;

struct Box {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
};

Box bounds(const Scene& scene, const Primitive& p) {
  Box b;
  for (std::uint32_t k = 0; k < p.point_count; ++k) {
    const Point2& q = scene.points[p.first_point + k];
    b.x0 = std::min(b.x0, q.x), b.x1 = std::max(b.x1, q.x);
    b.y0 = std::min(b.y0, q.y), b.y1 = std::max(b.y1, q.y);
  }
  return b;
}

void check_size(const Scene& scene, const Limits& limits) {
  const int max_w = std::min(limits.max_width, kMaxImageSide),
            max_h = std::min(limits.max_height, kMaxImageSide);
  if (scene.width > max_w || scene.height > max_h ||
      std::int64_t{scene.width} * scene.height > limits.max_pixels)
    throw SceneError(ErrorKind::limit, std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                                           " exceeds the image size limits");
  if (static_cast<std::int64_t>(scene.primitives.size()) > limits.max_primitives)
    throw SceneError(ErrorKind::limit, "too many primitives", {"/primitives", 0, 0});
}

const char* format_name(PixelFormat f) {
  switch (f) {
    case PixelFormat::grey8:
      return "grey8";
    case PixelFormat::grey_alpha8:
      return "grey_alpha8";
    case PixelFormat::rgb8:
      return "rgb8";
    case PixelFormat::rgba8:
      return "rgba8";
  }
  return "?";
}

[[noreturn]] void camera_error(const std::string& pointer, const std::string& message) {
  throw SceneError(ErrorKind::invalid, message, {pointer, 0, 0});
}

// World-space bounding box of every mesh's positions after its transform.
bool world_bounds(const Scene& scene, Vec3& lo, Vec3& hi) {
  bool any = false;
  lo = {INFINITY, INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY, -INFINITY};
  for (const Mesh& mesh : scene.meshes)
    for (const Vec3& p : mesh.positions) {
      const Vec3 w = detail::transform_point(mesh.transform, p);
      if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z)) continue;
      lo = {std::min(lo.x, w.x), std::min(lo.y, w.y), std::min(lo.z, w.z)};
      hi = {std::max(hi.x, w.x), std::max(hi.y, w.y), std::max(hi.z, w.z)};
      any = true;
    }
  return any;
}

// Fits whatever the scene's camera leaves out to the content, validates the result, builds the matrices.
ViewPlan resolve_view(const Scene& scene, double aspect) {
  using namespace detail;
  const Camera& cam = scene.camera;
  Vec3 lo, hi;
  if (!world_bounds(scene, lo, hi)) lo = {-1, -1, -1}, hi = {1, 1, 1};
  const Vec3 centre = (lo + hi) * 0.5;
  double radius = length(hi - lo) * 0.5;
  if (!(radius > 0)) radius = std::max(1.0, length(centre)) * 1e-6;  // a single point: any small sphere

  ViewPlan v;
  v.projection = cam.projection;
  v.fov_deg = cam.fov_deg;
  v.up = cam.up;
  v.target = cam.has_target ? cam.target : centre;
  // The side a fitted eye is on, and the up that goes with it when the scene gives none.
  Vec3 side_of_view{0, 0, 1};
  switch (cam.view) {
    case View::front:
      side_of_view = {0, 0, 1};
      break;
    case View::back:
      side_of_view = {0, 0, -1};
      break;
    case View::right:
      side_of_view = {1, 0, 0};
      break;
    case View::left:
      side_of_view = {-1, 0, 0};
      break;
    case View::top:
      side_of_view = {0, 1, 0};
      break;
    case View::bottom:
      side_of_view = {0, -1, 0};
      break;
    case View::iso:
      side_of_view = normalize(Vec3{1, 1, 1});
      break;
  }
  if (!cam.has_up && cam.view == View::top) v.up = {0, 0, -1};  // the front edge at the bottom, as in CAD
  if (!cam.has_up && cam.view == View::bottom) v.up = {0, 0, 1};
  const double half = cam.fov_deg * std::numbers::pi / 360.0;
  // Distance at which the bounding sphere fits the narrower of the two fields of view.
  const double tan_fit = std::min(std::tan(half), std::tan(half) * aspect);
  const double fit_distance = radius * std::sqrt(1 + tan_fit * tan_fit) / tan_fit;
  v.eye = cam.has_eye ? cam.eye : v.target + side_of_view * (fit_distance + length(v.target - centre));
  const Vec3 forward = normalize(v.target - v.eye);
  if (length(forward) == 0)  // only a fitted target can meet a given eye: validate() rejects the rest
    camera_error("/camera/eye",
                 "\"eye\" and \"target\" are the same point: the camera has no view direction");
  const Vec3 side = normalize(cross(forward, v.up));
  // sin of the angle between up and the view direction; below ~1e-9 the basis is not defined.
  if (length(side) == 0 || length(cross(forward, normalize(v.up))) < 1e-9)
    camera_error("/camera/up", "\"up\" is parallel to the view direction, so the image has no defined up");
  const Vec3 up = cross(side, forward);

  // Near and far: the content's extent along the view direction, unless given.
  double d_min = INFINITY, d_max = -INFINITY;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner{k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
    const double d = dot(corner - v.eye, forward);
    d_min = std::min(d_min, d), d_max = std::max(d_max, d);
  }
  v.far = cam.has_far ? cam.far : std::max(d_max * 1.01, 1e-9);
  // With the eye inside the content's box, content may be arbitrarily close: take a thousandth of the
  // distance to the target, as viewers do (not a fraction of `far`, which an outlying vertex can make
  // astronomically large). Reversed float depth keeps precision for near/far ratios down to ~1e-38.
  v.near = cam.has_near
               ? cam.near
               : (d_min > 0 ? d_min * 0.99 : std::max(length(v.target - v.eye) * 1e-3, v.far * 1e-30));
  if (!cam.has_far && v.near >= v.far) v.far = v.near * 2;
  if (!(v.near < v.far)) camera_error("/camera/near", "\"near\" must be less than \"far\"");
  v.height = cam.has_height ? cam.height : 2 * length(v.target - v.eye) * std::tan(half);

  Mat4 view;
  const Vec3 rows[3] = {side, up, forward * -1.0};
  for (int r = 0; r < 3; ++r) {
    view(r, 0) = rows[r].x, view(r, 1) = rows[r].y, view(r, 2) = rows[r].z;
    view(r, 3) = -dot(rows[r], v.eye);
  }
  Mat4 proj;  // maps view space (looking down -z) to clip space with reversed depth
  const double n = v.near, f = v.far;
  if (v.projection == Projection::perspective) {
    proj(0, 0) = 1 / (std::tan(half) * aspect);
    proj(1, 1) = 1 / std::tan(half);
    proj(2, 2) = n / (f - n), proj(2, 3) = n * f / (f - n);  // z = n (f - d) / (f - n) with d = -z_view
    proj(3, 2) = -1, proj(3, 3) = 0;                         // w = d
  } else {
    proj(0, 0) = 2 / (v.height * aspect);
    proj(1, 1) = 2 / v.height;
    proj(2, 2) = 1 / (f - n), proj(2, 3) = f / (f - n);  // z = (f - d) / (f - n), w = 1
  }
  v.world_to_clip = proj * view;
  // Lights into world space: a camera-space vector (x right, y up, z toward the viewer) is the same
  // combination of the view's own axes.
  auto from_camera = [&](const Vec3& c) { return side * c.x + up * c.y - forward * c.z; };
  for (const Light& light : scene.lights.empty() ? default_lights() : scene.lights) {
    LightPlan l;
    l.kind = light.kind;
    if (light.kind == LightKind::directional) {
      const Vec3 travel = normalize(light.camera_space ? from_camera(light.direction) : light.direction);
      l.to_light = travel * -1.0;
    }
    if (light.kind == LightKind::point)
      l.position = light.camera_space ? v.eye + from_camera(light.position) : light.position;
    l.rgb[0] = light.color.x * light.intensity, l.rgb[1] = light.color.y * light.intensity;
    l.rgb[2] = light.color.z * light.intensity;
    v.lights.push_back(l);
  }
  return v;
}

// Every buffer's size, worked out here once: the colour buffer (the output image), and each thread's tile
// storage, which the framebuffer allocates exactly as `out.tile_storage` says and MemoryPlan counts
// `out.threads` times. Reads the plan's format, coverage, samples, tile, threads and tiles_in_place.
void plan_buffers(RenderPlan& out, bool any_union) {
  const std::int64_t channels = channel_count(out.format), threads = out.threads;
  TileStoragePlan& t = out.tile_storage;
  // Each thread draws a tile at a time into storage of its own: the tile's colour and, for 3D, its depth
  // (the only depth buffer there is). Counted against the limit like the rest; small next to the image.
  t.pixels = std::int64_t{out.tile_width()} * out.tile_height();
  t.color_bytes = out.tiles_in_place ? 0 : t.pixels * channels;
  t.depth_floats = out.depth_buffer ? t.pixels * out.samples : 0;
  // Multisampling: a colour per sample, used only where a pixel's samples differ (one bit a pixel says so).
  t.sample_bytes = out.coverage == Coverage::samples ? t.pixels * out.samples * channels : 0;
  // Union coverage: its accumulation, and a bit a pixel saying which pixels were reached.
  t.coverage_floats = any_union ? t.pixels * kUnionFloats : 0;
  t.expanded_words = t.sample_bytes > 0 || t.coverage_floats > 0 ? t.pixels / 64 : 0;

  MemoryPlan& m = out.memory;
  const std::int64_t expanded_bytes = threads * t.expanded_words * std::int64_t{sizeof(std::uint64_t)};
  m.color_bytes = std::int64_t{out.width} * out.height * channels;
  m.tile_bytes = threads * t.color_bytes;
  m.depth_bytes = threads * t.depth_floats * std::int64_t{sizeof(float)};
  m.sample_bytes = t.sample_bytes > 0 ? threads * t.sample_bytes + expanded_bytes : 0;
  m.coverage_bytes = t.coverage_floats > 0 ? threads * t.coverage_floats * std::int64_t{sizeof(float)} + expanded_bytes : 0;
}

}  // namespace

Simd best_simd() {
#if defined(__x86_64__)
  if (__builtin_cpu_supports("avx2")) return Simd::avx2;
#endif
  return Simd::sse2;
}

RenderPlan plan(const Scene& scene, const Limits& limits, const PlanOptions& options) {
  validate(scene);
  check_size(scene, limits);

  RenderPlan out;
  out.width = scene.width;
  out.height = scene.height;

  const double w = scene.width, h = scene.height;
  const std::int64_t image_pixels = std::int64_t{scene.width} * scene.height;
  bool grey = scene.background.is_grey();
  const bool alpha = !scene.background.is_opaque();  // drawing over an opaque background stays opaque
  std::int64_t work = 0;
  std::int64_t vertices_3d = 0;  // corners of the visible meshes, for the budget

  bool any_3d = false, any_union = false;
  // Lit colours stay grey only under grey lights; point lights need the world position of each pixel.
  bool grey_lights = true, point_lights = false;
  for (const Light& l : scene.lights) {
    grey_lights &= l.color.x == l.color.y && l.color.y == l.color.z;
    point_lights |= l.kind == LightKind::point;
  }
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& prim = scene.primitives[i];
    DrawPlan draw;
    draw.primitive = static_cast<std::uint32_t>(i);
    PrimitivePlan& pp = draw.mode;
    if (prim.kind == PrimitiveKind::mesh) {
      const Mesh& mesh = scene.meshes[prim.mesh];
      const bool draws_triangles = !mesh.triangles.empty() && !mesh.wireframe;
      if (mesh.triangles.empty() && mesh.segments.empty()) {
        ++out.culled_count;
        continue;
      }
      any_3d = true;
      pp.depth = true;
      pp.lit = draws_triangles && mesh.shading != Shading::unlit;
      pp.light_per_pixel = pp.lit && mesh.shading == Shading::smooth;
      pp.compute_normals = pp.light_per_pixel && mesh.normals.empty();
      pp.position_per_pixel = pp.light_per_pixel && point_lights;
      grey &= grey_lights || !pp.lit;
      const auto& colors = mesh.face_colors.empty() ? mesh.colors : mesh.face_colors;
      bool varied = false;
      for (const Rgba8& c : colors) {
        varied |= !(c == colors[0]);
        pp.blend |= !c.is_opaque();
        grey &= c.is_grey();
      }
      // Per-pixel work when colours vary per vertex or normals are interpolated; per-face colours and flat
      // lighting give one colour per triangle.
      pp.varying_color = varied && mesh.face_colors.empty() && mesh.colors.size() > 1;
      // Textures: sampled per pixel at perspective-correct coordinates, so the mesh takes the smooth path.
      pp.textured = draws_triangles && !mesh.textures.empty() && !mesh.uv_triangles.empty();
      if (pp.textured) {
        for (const Texture& t : mesh.textures) {
          bool opaque = true, grey_texels = true;
          for (std::size_t k = 0; k + 3 < t.rgba.size(); k += 4) {
            opaque &= t.rgba[k + 3] == 255;
            grey_texels &= t.rgba[k] == t.rgba[k + 1] && t.rgba[k + 1] == t.rgba[k + 2];
          }
          pp.blend |= !opaque;
          grey &= grey_texels;
          out.memory.texture_bytes +=
              static_cast<std::int64_t>(t.rgba.size()) + detail::mip_bytes(t.width, t.height);
        }
        ++out.textured_count;
      }
      pp.smooth = pp.varying_color || pp.textured || (pp.lit && mesh.shading == Shading::smooth);
      // Lines (segments, wireframe edges) are unlit; their endpoint colours differ when the colours vary.
      draw.line_mode.depth = true;
      draw.line_mode.blend = pp.blend;
      draw.line_mode.smooth = draw.line_mode.varying_color = varied;
      if (mesh.edges.enabled && draws_triangles) {
        draw.edge_mode.depth = true;
        draw.edge_mode.blend = !mesh.edges.color.is_opaque();
        draw.edge_mode.line_rectangles = mesh.edges.width != 1;  // (and when multisampled, below)
        grey &= mesh.edges.color.is_grey();
      }
      (pp.smooth ? out.smooth_count : out.flat_count) += 1;
      out.blend_count += pp.blend ? 1 : 0;
      out.lit_count += pp.lit ? 1 : 0;
      out.triangles_3d += draws_triangles ? static_cast<std::int64_t>(mesh.triangles.size()) : 0;
      vertices_3d += static_cast<std::int64_t>(mesh.positions.size() + mesh.segments.size() * 2);
      work += image_pixels;  // a mesh may cover the whole image
      out.draws.push_back(draw);
      continue;
    }
    const bool filled = prim.kind == PrimitiveKind::triangle && prim.fill;
    pp.line_rectangles = !filled && (scene.antialias != Antialias::none || prim.width != 1);
    pp.union_coverage = pp.line_rectangles && scene.antialias == Antialias::area;
    any_union |= pp.union_coverage;
    Box b = bounds(scene, prim);
    if (!filled) {  // a wide line reaches half its width beyond its points
      const double pad = prim.width * 0.5;
      b.x0 -= pad, b.y0 -= pad, b.x1 += pad, b.y1 += pad;
    }
    // Conservative: a primitive touching the image's closed rectangle is kept.
    if (!(b.x1 >= 0 && b.x0 <= w && b.y1 >= 0 && b.y0 <= h)) {
      ++out.culled_count;
      continue;
    }
    const std::uint32_t ncolors = prim.per_vertex_color ? prim.point_count : 1;
    const Rgba8 first = scene.colors[prim.first_color];
    for (std::uint32_t k = 0; k < ncolors; ++k) {
      const Rgba8 c = scene.colors[prim.first_color + k];
      pp.smooth |= !(c == first);
      pp.blend |= !c.is_opaque();
      grey &= c.is_grey();
    }
    pp.varying_color = pp.smooth;
    (pp.smooth ? out.smooth_count : out.flat_count) += 1;
    out.blend_count += pp.blend ? 1 : 0;
    const double cw = std::min(b.x1, w) - std::max(b.x0, 0.0) + 1,
                 ch = std::min(b.y1, h) - std::max(b.y0, 0.0) + 1;
    work += static_cast<std::int64_t>(filled ? cw * ch : std::max(cw, ch));
    out.draws.push_back(draw);
  }

  work *= sample_count(scene.antialias);  // every sample plane is drawn
  out.format = grey ? (alpha ? PixelFormat::grey_alpha8 : PixelFormat::grey8)
                    : (alpha ? PixelFormat::rgba8 : PixelFormat::rgb8);
  // "area" is exact for 2D shapes composited one after another; with depth the share of a pixel each
  // triangle covers is not what is visible (and abutting mesh triangles would seam), so 3D gets samples.
  const bool area = scene.antialias == Antialias::area;
  out.samples = sample_count(area && any_3d ? kAreaFallback3d : scene.antialias);
  out.coverage = area && !any_3d     ? Coverage::area
                 : out.samples > 1 ? Coverage::samples
                                   : Coverage::centre;
  if (area && any_3d)
    for (DrawPlan& d : out.draws) d.mode.union_coverage = false, any_union = false;
  // Multisampled 3D lines are rectangles a pixel wide, so their edges are covered per sample like the rest.
  for (DrawPlan& d : out.draws) {
    d.line_mode.line_rectangles = d.line_mode.depth && out.samples > 1;
    d.edge_mode.line_rectangles |= d.edge_mode.depth && out.samples > 1;
  }
  if (any_3d) {
    out.depth_buffer = true;
    out.view = resolve_view(scene, static_cast<double>(scene.width) / scene.height);
  }

  const int cores = options.max_threads > 0
                        ? options.max_threads
                        : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  out.work = work;
  const bool small = image_pixels <= kSmallScenePixels && scene.primitives.size() <= kSmallScenePrimitives;
  // Small images are one tile: binning a thumbnail costs more than it saves.
  const int one_tile = (std::max(scene.width, scene.height) + 7) / 8 * 8;
  // Multisampling keeps a colour per sample of a tile: 64 px tiles keep that in the cache (and reuse its
  // pages) however small the image.
  out.tile = options.tile > 0                                        ? (options.tile + 7) / 8 * 8
             : image_pixels <= kSmallScenePixels && out.samples == 1 ? one_tile
             : out.samples > 1                                       ? std::min(kSampleTile, one_tile)
                                                                     : std::min(kTile, one_tile);
  const int tiles = ((scene.width + out.tile - 1) / out.tile) * ((scene.height + out.tile - 1) / out.tile);
  out.threads = small || work < kParallelWorkThreshold ? 1 : std::clamp(tiles, 1, cores);
  out.scalar_coverage = options.scalar_coverage;
  out.simd = std::min(best_simd(), options.max_simd);
  out.tiles_in_place = !any_3d && out.coverage == Coverage::centre && scene.width % 8 == 0;
  plan_buffers(out, any_union);
  if (out.memory.total() > limits.max_buffer_bytes || out.memory.total() < 0)
    throw SceneError(ErrorKind::limit, "the render needs " + std::to_string(out.memory.total()) +
                                           " bytes of pixel storage, over the limit of " +
                                           std::to_string(limits.max_buffer_bytes));
  // Asked for now that it is known: the pixel storage, the PNG (at most about the colour buffer's size), and
  // the setup's records and transformed corners. The bins are asked for by the render once counted.
  detail::reserve(limits,
                  out.memory.total() + out.memory.color_bytes + cost::kRenderPerTriangle * out.triangles_3d +
                      cost::kRenderPerVertex * vertices_3d +
                      cost::kRenderPerPrimitive * static_cast<std::int64_t>(out.draws.size()),
                  [&] {
                    return "rendering " + std::to_string(out.draws.size()) + " primitives (" +
                           std::to_string(out.triangles_3d) + " mesh triangles) at " +
                           std::to_string(out.width) + "x" + std::to_string(out.height);
                  });
  out.png = png_plan_for(out.format);
  return out;
}

PngPlan png_plan_for(PixelFormat format) {
  PngPlan png;
  switch (format) {
    case PixelFormat::grey8:
      png.color_type = 0;
      break;
    case PixelFormat::grey_alpha8:
      png.color_type = 4;
      break;
    case PixelFormat::rgb8:
      png.color_type = 2;
      break;
    case PixelFormat::rgba8:
      png.color_type = 6;
      break;
  }
  return png;
}

const DrawPlan* RenderPlan::draw_of(std::uint32_t index) const {
  const auto it = std::lower_bound(draws.begin(), draws.end(), index,
                                   [](const DrawPlan& d, std::uint32_t i) { return d.primitive < i; });
  return it != draws.end() && it->primitive == index ? &*it : nullptr;
}

std::string explain_json(const RenderPlan& p) {
  nlohmann::ordered_json j;
  j["width"] = p.width;
  j["height"] = p.height;
  j["format"] = format_name(p.format);
  j["channels"] = channel_count(p.format);
  j["depth_buffer"] = p.depth_buffer;
  j["samples"] = p.samples;
  j["simd"] = p.simd == Simd::avx2 ? "avx2" : "sse2";
  j["tiles_in_place"] = p.tiles_in_place;
  j["antialias"] = p.coverage == Coverage::area      ? "area"
                   : p.coverage == Coverage::samples ? "multisample"
                                                     : "none";
  j["primitives"] = {{"flat", p.flat_count},        {"smooth", p.smooth_count},
                     {"blend", p.blend_count},      {"culled", p.culled_count},
                     {"lit", p.lit_count},          {"triangles_3d", p.triangles_3d},
                     {"textured", p.textured_count}};
  if (p.depth_buffer) {
    const ViewPlan& v = p.view;
    j["camera"] = {{"projection", v.projection == Projection::perspective ? "perspective" : "orthographic"},
                   {"eye", {v.eye.x, v.eye.y, v.eye.z}},
                   {"target", {v.target.x, v.target.y, v.target.z}},
                   {"up", {v.up.x, v.up.y, v.up.z}},
                   {"fov", v.fov_deg},
                   {"near", v.near},
                   {"far", v.far},
                   {"height", v.height}};
  }
  if (p.lit_count > 0) {  // in world space, as resolved for this view
    nlohmann::ordered_json lights = nlohmann::ordered_json::array();
    for (const LightPlan& l : p.view.lights) {
      nlohmann::ordered_json o;
      o["type"] = l.kind == LightKind::ambient ? "ambient"
                  : l.kind == LightKind::point ? "point"
                                               : "directional";
      if (l.kind == LightKind::directional) o["toward_light"] = {l.to_light.x, l.to_light.y, l.to_light.z};
      if (l.kind == LightKind::point) o["position"] = {l.position.x, l.position.y, l.position.z};
      o["rgb"] = {l.rgb[0], l.rgb[1], l.rgb[2]};
      lights.push_back(o);
    }
    j["lights"] = lights;
  }
  j["work"] = p.work;
  j["threads"] = p.threads;
  j["tile"] = p.tile;
  j["memory_bytes"] = {{"color", p.memory.color_bytes},
                       {"depth", p.memory.depth_bytes},
                       {"samples", p.memory.sample_bytes},
                       {"tiles", p.memory.tile_bytes},
                       {"coverage", p.memory.coverage_bytes},
                       {"textures", p.memory.texture_bytes},
                       {"total", p.memory.total()}};
  j["png"] = {{"color_type", p.png.color_type}, {"deflate_level", p.png.deflate_level}};
  return j.dump(2);
}

std::string explain_line(const RenderPlan& p) {
  return std::string(format_name(p.format)) + " depth=" + (p.depth_buffer ? "f32" : "none") +
         " samples=" + (p.coverage == Coverage::area ? std::string("area") : std::to_string(p.samples)) +
         " flat=" + std::to_string(p.flat_count) + " smooth=" + std::to_string(p.smooth_count) +
         " blend=" + std::to_string(p.blend_count) + " culled=" + std::to_string(p.culled_count) +
         (p.lit_count ? " lit=" + std::to_string(p.lit_count) : "") + " threads=" + std::to_string(p.threads);
}

}  // namespace raster
