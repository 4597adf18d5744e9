// The plan stage: every "does this scene need X" decision, made once, from the scene alone: a pass over the
// primitives (how each is drawn, the pixel format, the work), then the coverage, the view (plan/view.cpp),
// the tiles and threads, and every buffer's size, checked against the limits and reserved.
#include "raster/plan.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "base/budget_ask.h"
#include "base/grid.h"
#include "base/mip_chain.h"
#include "plan/shaders.h"
#include "plan/view.h"

namespace raster {

VaryingLayout VaryingLayout::of(Varyings varyings) {
  VaryingLayout l;
  l.floats = l.clipped_floats = l.flat_floats = l.stride = 0;
  for (int i = 0; i < kVaryingCount; ++i) {
    const Varying v = static_cast<Varying>(i);
    if (!varyings.has(v)) {
      l.vertex_offset[i] = l.record_offset[i] = -1;
      continue;
    }
    const std::uint8_t width = kVaryingWidth[i];
    l.interpolation[i] = varyings.how(v);
    l.vertex_offset[i] = static_cast<std::int8_t>(l.floats);
    l.floats += width;
    if (i < static_cast<int>(Varying::depth)) l.clipped_floats = l.floats;
    std::uint8_t& block = l.interpolation[i] == Interpolation::flat ? l.flat_floats : l.stride;
    l.record_offset[i] = static_cast<std::int8_t>(block);
    block += width;
  }
  return l;
}
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
// "auto": the samples its edge blocks are drawn at (docs/accuracy.md measures 4, 8 and 16 there).
constexpr Antialias kEdgeSampling = Antialias::msaa8;

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

// What the scene's lights do to the plan: lit colours stay grey only under grey lights, and point lights need
// each lit pixel's world position.
struct LightFacts {
  bool grey = true;    // every light's colour is grey (r = g = b)
  bool point = false;  // some light is a point light
};

LightFacts light_facts(const Scene& scene) {
  LightFacts f;
  // The lights the view will place (plan/light.cpp): the scene's, or the default rig when it has none.
  for (const Light& l : scene.lights.empty() ? default_lights() : scene.lights) {
    f.grey &= l.color.x == l.color.y && l.color.y == l.color.z;
    f.point |= l.kind == LightKind::point;
  }
  return f;
}

// What the pass over the primitives found, for the decisions made after it.
struct Tally {
  bool grey = true;             // every colour the render can make is grey
  bool any_3d = false;          // some mesh is drawn: depth, a view, multisampled area
  bool any_union = false;       // some 2D primitive has union coverage (area accumulation storage)
  std::int64_t work = 0;        // estimated pixel writes, before the samples (RenderPlan::work)
  std::int64_t mesh_bytes = 0;  // what geometry holds for the visible meshes besides records (budget.h)
};

// What geometry holds for a mesh besides its records (budget.h's per-vertex, per-normal, per-edge and
// per-segment costs): asked of the budget by the plan.
std::int64_t geometry_bytes(const Mesh& mesh, const PrimitivePlan& pp, bool draws_triangles) {
  const auto vertices = static_cast<std::int64_t>(mesh.positions.size());
  const bool transformed = !(mesh.transform == Mat4{});
  const std::int64_t normals = pp.compute_normals ? vertices
                               : pp.varyings.has(Varying::normal)
                                   ? static_cast<std::int64_t>(mesh.normals.size())
                                   : 0;
  const bool edge_list = mesh.wireframe || (mesh.edges.enabled && draws_triangles);
  return vertices * (cost::kRenderPerVertex + (transformed ? cost::kRenderPerWorldVertex : 0)) +
         normals * cost::kRenderPerNormal +
         (edge_list ? cost::kRenderPerEdgeTriangle * static_cast<std::int64_t>(mesh.triangles.size()) : 0) +
         cost::kRenderPerSegment * static_cast<std::int64_t>(mesh.segments.size());
}

// The textures of a textured mesh: whether they blend or break grey, and their bytes with the mipmaps.
void plan_textures(const Mesh& mesh, PrimitivePlan& pp, RenderPlan& out, Tally& tally) {
  // A texture only a material reads (metallic-roughness) holds numbers, not colours: its texels neither
  // blend nor colour. Found once, and only for meshes with such a material.
  std::vector<bool> numbers_only;
  for (const Material& m : mesh.materials)
    if (m.metallic_roughness_texture >= 0) {
      if (numbers_only.empty()) {
        numbers_only.assign(mesh.textures.size(), false);
        for (const Material& n : mesh.materials)
          if (n.metallic_roughness_texture >= 0)
            numbers_only[static_cast<std::size_t>(n.metallic_roughness_texture)] = true;
        if (mesh.face_textures.empty()) numbers_only[0] = false;
        for (std::int32_t f : mesh.face_textures)
          if (f >= 0) numbers_only[static_cast<std::size_t>(f)] = false;
      }
      break;
    }
  for (std::size_t i = 0; i < mesh.textures.size(); ++i) {
    const Texture& t = mesh.textures[i];
    out.memory.texture_bytes +=
        static_cast<std::int64_t>(t.rgba.size()) + detail::mip_bytes(t.width, t.height);
    if (!numbers_only.empty() && numbers_only[i]) continue;
    bool opaque = true, grey_texels = true, cut_outs = false;
    for (std::size_t k = 0; k + 3 < t.rgba.size(); k += 4) {
      opaque &= t.rgba[k + 3] == 255;
      cut_outs |= t.rgba[k + 3] == 0;
      grey_texels &= t.rgba[k] == t.rgba[k + 1] && t.rgba[k + 1] == t.rgba[k + 2];
    }
    pp.blend |= !opaque;
    pp.cut_outs |= cut_outs;
    tally.grey &= grey_texels;
  }
  ++out.textured_count;
}

// A mesh's draw: its triangles' mode (lighting, colours, textures), its lines' and its feature edges'.
// False when it has nothing to draw (then it is culled).
bool plan_mesh(const Mesh& mesh, const LightFacts& lights, DrawPlan& draw, RenderPlan& out, Tally& tally) {
  if (mesh.triangles.empty() && mesh.segments.empty() && mesh.points.empty()) return false;
  PrimitivePlan& pp = draw.mode;
  const bool draws_triangles = !mesh.triangles.empty() && !mesh.wireframe;
  tally.any_3d = true;
  pp.depth = true;
  pp.lit = draws_triangles && mesh.shading != Shading::unlit;
  // Specular: some face's material adds to Lambert. Such a mesh is lit per pixel (the highlight moves with
  // the view direction across a face), flat-shaded ones with each face's own normal.
  bool any_specular = false;
  for (const Material& m : mesh.materials) {
    any_specular |= m.is_specular();
    // A coloured Ks makes colours that are not grey (a metal's F0 is its grey or coloured base colour).
    if (m.model == Material::Model::blinn_phong && m.is_specular())
      tally.grey &= m.specular[0] == m.specular[1] && m.specular[1] == m.specular[2];
  }
  pp.specular = pp.lit && any_specular;
  pp.face_normals = pp.specular && mesh.shading == Shading::flat;
  const bool light_per_pixel = pp.lit && (mesh.shading == Shading::smooth || pp.specular);
  pp.compute_normals = light_per_pixel && !pp.face_normals && mesh.normals.empty();
  pp.normals_where_drawn =
      pp.compute_normals && mesh.triangles.size() > static_cast<std::size_t>(out.width) * out.height;
  tally.grey &= lights.grey || !pp.lit;
  const auto& colors = mesh.face_colors.empty() ? mesh.colors : mesh.face_colors;
  bool varied = false;
  for (const Rgba8& c : colors) {
    varied |= !(c == colors[0]);
    pp.blend |= !c.is_opaque();
    tally.grey &= c.is_grey();
  }
  // Per-pixel work when colours vary per vertex or normals are interpolated; per-face colours and flat
  // lighting give one colour per triangle.
  const bool varying_color = varied && mesh.face_colors.empty() && mesh.colors.size() > 1;
  // Textures: sampled per pixel at perspective-correct coordinates, so the mesh takes the smooth path.
  const bool textured = draws_triangles && !mesh.textures.empty() && !mesh.uv_triangles.empty();
  if (textured) plan_textures(mesh, pp, out, tally);
  pp.smooth = varying_color || textured || light_per_pixel;
  Varyings& v = pp.varyings;
  if (varying_color) v.add(Varying::color, Interpolation::perspective);
  if (light_per_pixel) v.add(Varying::normal, Interpolation::perspective);
  if (textured) v.add(Varying::uv, Interpolation::perspective);
  if (light_per_pixel && (lights.point || pp.specular)) v.add(Varying::position, Interpolation::perspective);
  v.add(Varying::depth, Interpolation::affine);
  if (pp.smooth) v.add(Varying::inv_w, Interpolation::affine);
  // Lines (segments, wireframe edges) are unlit; their endpoint colours differ when the colours vary.
  draw.line_mode.depth = true;
  draw.line_mode.blend = pp.blend;
  draw.line_mode.smooth = varied;
  if (varied) draw.line_mode.varyings.add(Varying::color, Interpolation::perspective);
  draw.line_mode.varyings.add(Varying::depth, Interpolation::affine);
  if (varied) draw.line_mode.varyings.add(Varying::inv_w, Interpolation::affine);
  if (mesh.edges.enabled && draws_triangles) {
    draw.edge_mode.depth = true;
    draw.edge_mode.blend = !mesh.edges.color.is_opaque();
    draw.edge_mode.line_rectangles = mesh.edges.width != 1;  // (and when multisampled, see plan_coverage)
    draw.edge_mode.varyings.add(Varying::depth, Interpolation::affine);
    tally.grey &= mesh.edges.color.is_grey();
  }
  if (!mesh.points.empty()) {
    // Points are unlit (they carry no normal) and take their vertex's colour, one a point: a flat colour per
    // record, depth-tested like the faces.
    draw.point_mode.depth = true;
    for (const Rgba8& c : mesh.colors) {
      draw.point_mode.blend |= !c.is_opaque();
      tally.grey &= c.is_grey();
    }
    draw.point_mode.varyings.add(Varying::depth, Interpolation::affine);
    out.points_3d += static_cast<std::int64_t>(mesh.points.size());
  }
  (pp.smooth ? out.smooth_count : out.flat_count) += 1;
  out.blend_count += pp.blend || draw.point_mode.blend ? 1 : 0;
  out.lit_count += pp.lit ? 1 : 0;
  out.triangles_3d += draws_triangles ? static_cast<std::int64_t>(mesh.triangles.size()) : 0;
  tally.mesh_bytes += geometry_bytes(mesh, pp, draws_triangles);
  tally.work += std::int64_t{out.width} * out.height;  // a mesh may cover the whole image
  return true;
}

// A 2D primitive's draw: lines as rectangles or not, union coverage, colours. False when its bounding box
// misses the image (then it is culled).
bool plan_shape(const Scene& scene, const Primitive& prim, DrawPlan& draw, RenderPlan& out, Tally& tally) {
  PrimitivePlan& pp = draw.mode;
  const double w = scene.width, h = scene.height;
  const bool filled = prim.kind == PrimitiveKind::triangle && prim.fill;
  pp.line_rectangles = !filled && (scene.antialias != Antialias::none || prim.width != 1);
  Box b = bounds(scene, prim);
  if (!filled) {  // a wide line reaches half its width beyond its points
    const double pad = prim.width * 0.5;
    b.x0 -= pad, b.y0 -= pad, b.x1 += pad, b.y1 += pad;
  }
  // Conservative: a primitive touching the image's closed rectangle is kept.
  if (!(b.x1 >= 0 && b.x0 <= w && b.y1 >= 0 && b.y0 <= h)) return false;
  const std::uint32_t ncolors = prim.per_vertex_color ? prim.point_count : 1;
  const Rgba8 first = scene.colors[prim.first_color];
  for (std::uint32_t k = 0; k < ncolors; ++k) {
    const Rgba8 c = scene.colors[prim.first_color + k];
    pp.smooth |= !(c == first);
    pp.blend |= !c.is_opaque();
    tally.grey &= c.is_grey();
  }
  if (pp.smooth) pp.varyings.add(Varying::color, Interpolation::affine);
  // One colour and every corner (the points, padded by half the width) in the fast range: quads. A single
  // segment as a quad is one shape; anything else drawn as rectangles adds up its pieces' coverage.
  constexpr double kFast = detail::kFastRangePx - 1;  // room for snapping
  pp.line_quads =
      pp.line_rectangles && !pp.smooth && b.x0 >= -kFast && b.y0 >= -kFast && b.x1 <= kFast && b.y1 <= kFast;
  const bool one_segment = prim.point_count == 2;
  pp.union_coverage =
      pp.line_rectangles && scene.antialias == Antialias::area && !(pp.line_quads && one_segment);
  tally.any_union |= pp.union_coverage;
  (pp.smooth ? out.smooth_count : out.flat_count) += 1;
  out.blend_count += pp.blend ? 1 : 0;
  const double cw = std::min(b.x1, w) - std::max(b.x0, 0.0) + 1,
               ch = std::min(b.y1, h) - std::max(b.y0, 0.0) + 1;
  tally.work += static_cast<std::int64_t>(filled ? cw * ch : std::max(cw, ch));
  return true;
}

// A shader's draw (plan/shaders.cpp), and what it means for the rest: colours of every kind, and work that
// grows with its program (a pixel of a program costs about one of a triangle per 16 instructions).
bool plan_program(const Scene& scene, std::uint32_t index, const Limits& limits, const PlanOptions& options,
                  DrawPlan& draw, RenderPlan& out, Tally& tally) {
  if (!detail::plan_shader(scene, index, limits, options.shader_cache, out, draw)) return false;
  const ShaderPlan& p = out.shaders.back();
  tally.grey = false;
  ++out.shader_count;
  const std::int64_t pixels = std::int64_t{p.x1 - p.x0} * (p.y1 - p.y0);
  tally.work += pixels * std::max<std::int64_t>(1, static_cast<std::int64_t>(p.shader->instructions()) / 16);
  return true;
}

// The pass over the primitives: a draw for each visible one, in scene order, and the counts.
Tally plan_draws(const Scene& scene, const Limits& limits, const PlanOptions& options, RenderPlan& out) {
  Tally tally;
  tally.grey = scene.background.is_grey();
  const LightFacts lights = light_facts(scene);
  // Each draw is planned where it is kept, not copied there (a culled one is taken back). Not reserved for
  // every primitive: culled ones would hold memory the plan's estimate, which counts draws, does not.
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& prim = scene.primitives[i];
    DrawPlan& draw = out.draws.emplace_back();
    draw.primitive = static_cast<std::uint32_t>(i);
    const bool visible =
        prim.kind == PrimitiveKind::mesh ? plan_mesh(scene.meshes[prim.mesh], lights, draw, out, tally)
        : prim.kind == PrimitiveKind::shader
            ? plan_program(scene, static_cast<std::uint32_t>(i), limits, options, draw, out, tally)
            : plan_shape(scene, prim, draw, out, tally);
    if (!visible) {
      out.draws.pop_back();
      ++out.culled_count;
    }
  }
  return tally;
}

// The one anti-aliasing decision: the scene's Antialias -> RenderPlan::coverage and ::samples, and what
// follows for the draws (area's union coverage gives way to samples in 3D; multisampled 3D lines are
// rectangles). "area" is exact for 2D shapes composited one after another; with depth the share of a pixel
// each triangle covers is not what is visible (and abutting mesh triangles would seam), so 3D gets samples.
void plan_coverage(Antialias antialias, RenderPlan& out, Tally& tally) {
  const bool area = antialias == Antialias::area;
  if (antialias == Antialias::automatic) {
    out.samples = sample_count(kEdgeSampling);
    out.coverage = Coverage::edge_samples;
  } else {
    out.samples = sample_count(area && tally.any_3d ? kAreaFallback3d : antialias);
    out.coverage = area && !tally.any_3d ? Coverage::area
                   : out.samples > 1     ? Coverage::samples
                                         : Coverage::centre;
  }
  if (area && tally.any_3d)
    for (DrawPlan& d : out.draws) d.mode.union_coverage = false, tally.any_union = false;
  // A program is evaluated at each sample position of a multisampled pixel (auto: of an edge pixel).
  for (ShaderPlan& p : out.shaders) p.samples = multisampled(out.coverage) ? out.samples : 1;
  // Multisampled 3D lines are rectangles a pixel wide, so their edges are covered per sample like the rest.
  for (DrawPlan& d : out.draws) {
    d.line_mode.line_rectangles = d.line_mode.depth && out.samples > 1;
    d.edge_mode.line_rectangles |= d.edge_mode.depth && out.samples > 1;
  }
}

// The tile side and the thread count, from the image's size, the work and the caller's options.
void plan_threads(const Scene& scene, const PlanOptions& options, RenderPlan& out) {
  const int cores = options.max_threads > 0
                        ? options.max_threads
                        : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const std::int64_t image_pixels = std::int64_t{scene.width} * scene.height;
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
  out.threads = small || out.work < kParallelWorkThreshold ? 1 : std::clamp(tiles, 1, cores);
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
  t.sample_bytes = multisampled(out.coverage) ? t.pixels * out.samples * channels : 0;
  // Union coverage: its accumulation, and a bit a pixel saying which pixels were reached.
  t.coverage_floats = any_union ? t.pixels * kUnionFloats : 0;
  t.expanded_words = t.sample_bytes > 0 || t.coverage_floats > 0 ? t.pixels / 64 : 0;

  MemoryPlan& m = out.memory;
  const std::int64_t expanded_bytes = threads * t.expanded_words * std::int64_t{sizeof(std::uint64_t)};
  m.color_bytes = std::int64_t{out.width} * out.height * channels;
  m.tile_bytes = threads * t.color_bytes;
  m.depth_bytes = threads * t.depth_floats * std::int64_t{sizeof(float)};
  m.sample_bytes = t.sample_bytes > 0 ? threads * t.sample_bytes + expanded_bytes : 0;
  m.coverage_bytes =
      t.coverage_floats > 0 ? threads * t.coverage_floats * std::int64_t{sizeof(float)} + expanded_bytes : 0;
  // Edge sampling finds its edge pixels once over the whole image (shade/edges.cpp allocates exactly this).
  const std::int64_t blocks = std::int64_t{(out.width + 7) / 8} * ((out.height + 7) / 8);
  for (const ShaderPlan& p : out.shaders) m.shader_bytes += threads * p.register_bytes;
  m.edge_bytes = out.coverage == Coverage::edge_samples
                     ? blocks * std::int64_t{sizeof(std::uint64_t)} + std::max(out.width - 1, 1) * channels
                     : 0;
}

// The pixel storage against the limit, then what the render will allocate asked of the budget: the pixel
// storage, the PNG (at most about the colour buffer's size), the 2D records and the meshes' transformed
// vertices and normals. A mesh's records are asked for as geometry makes them, the bins once counted.
void check_memory(const Limits& limits, const RenderPlan& out, std::int64_t mesh_bytes) {
  if (out.memory.total() > limits.max_buffer_bytes || out.memory.total() < 0)
    throw SceneError(ErrorKind::limit, "the render needs " + std::to_string(out.memory.total()) +
                                           " bytes of pixel storage, over the limit of " +
                                           std::to_string(limits.max_buffer_bytes));
  detail::reserve(limits,
                  cost::kRenderPerThread * out.threads + out.memory.total() + out.memory.color_bytes +
                      mesh_bytes + cost::kRenderPerPrimitive * static_cast<std::int64_t>(out.draws.size()),
                  [&] {
                    return "rendering " + std::to_string(out.draws.size()) + " primitives (" +
                           std::to_string(out.triangles_3d) + " mesh triangles) at " +
                           std::to_string(out.width) + "x" + std::to_string(out.height);
                  });
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
  Tally tally = plan_draws(scene, limits, options, out);
  const bool alpha = !scene.background.is_opaque();  // drawing over an opaque background stays opaque
  out.format = tally.grey ? (alpha ? PixelFormat::grey_alpha8 : PixelFormat::grey8)
                          : (alpha ? PixelFormat::rgba8 : PixelFormat::rgb8);
  plan_coverage(scene.antialias, out, tally);
  // Every sample plane is drawn: after the coverage decision, which gives a 3D "area" render 8 samples.
  out.work = tally.work * out.samples;
  if (tally.any_3d) {
    out.depth_buffer = true;
    out.view = detail::resolve_view(scene, static_cast<double>(scene.width) / scene.height);
  }
  plan_threads(scene, options, out);
  out.scalar_coverage = options.scalar_coverage;
  out.scalar_shading = options.scalar_shading;
  out.keep_samples = options.keep_samples;
  out.simd = std::min(best_simd(), options.max_simd);
  out.tiles_in_place = !tally.any_3d && out.coverage == Coverage::centre && scene.width % 8 == 0;
  plan_buffers(out, tally.any_union);
  check_memory(limits, out, tally.mesh_bytes);
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

}  // namespace raster
