// Plan: Scene -> RenderPlan, every decision about what this render needs (buffers, per-primitive modes,
// camera, tiles, threads, PNG colour type, every buffer's size), made once before any pixel work. Geometry,
// setup, the tiles and the encoder execute a plan and decide nothing that shows in the image; the one
// choice left to them is how to cut their work among the plan's threads (geometry's pieces of a large
// mesh, parallel.h), which changes who computes a record, never what it holds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "raster/image.h"
#include "raster/scene.h"
#include "raster/shader.h"

namespace raster {

/// What a vertex carries to the pixels beside its position: one row each, in this order (the order of a
/// vertex's floats). Adding one is a row here, its width in kVaryingWidth, the plan's decision to add it, and
/// the code that writes and reads it; clipping, setup and the planes the shader reads follow this
/// description.
enum class Varying : std::uint8_t {
  color,     ///< straight RGBA, 0..255 (3D flat lighting already applied)
  normal,    ///< world-space unit normal (per-pixel lighting)
  uv,        ///< texture coordinates (scene.h: Mesh::uvs)
  position,  ///< world position (per-pixel lighting by a point light; the view direction of specular faces)
  depth,     ///< z / w in [0, 1], 1 at the near plane (reversed); written by the viewport, not clipped
  inv_w,     ///< 1 / w, for perspective-correct interpolation; written by the viewport, not clipped
};
inline constexpr int kVaryingCount = 6;
/// Floats of each Varying, in enum order.
inline constexpr std::uint8_t kVaryingWidth[kVaryingCount] = {4, 3, 2, 3, 1, 1};

/// Floats of every row together.
inline constexpr int kVaryingFloats = [] {
  int sum = 0;
  for (const std::uint8_t width : kVaryingWidth) sum += width;
  return sum;
}();

/// How a varying changes across a triangle.
enum class Interpolation : std::uint8_t {
  flat,         ///< one value for the whole primitive: its first vertex's (stored once per record)
  affine,       ///< linear in screen space: 2D colours, and depth and 1 / w (affine after the divide)
  perspective,  ///< linear in the world: v / w and 1 / w interpolated in screen space, then divided
};

/// The varyings of a primitive, decided by the plan: which rows exist and how each is interpolated, two bits
/// a row (0: absent, else 1 + Interpolation), so that the four modes of every DrawPlan stay small (a scene
/// of 100,000 triangles has 100,000 of them). Setup lays it out once per draw call (VaryingLayout).
struct Varyings {
  std::uint16_t rows = 1;  ///< bits 2i..2i+1: row i; the default is a flat colour alone

  bool has(Varying v) const { return (rows >> (2 * static_cast<int>(v)) & 3) != 0; }
  Interpolation how(Varying v) const {
    return static_cast<Interpolation>((rows >> (2 * static_cast<int>(v)) & 3) - 1);
  }
  /// Adds (or re-interpolates) a row.
  Varyings& add(Varying v, Interpolation how) {
    const int shift = 2 * static_cast<int>(v);
    rows = static_cast<std::uint16_t>((rows & ~(3 << shift)) | (static_cast<int>(how) + 1) << shift);
    return *this;
  }
  friend bool operator==(const Varyings&, const Varyings&) = default;
};

/// Where a Varyings' rows live, the layout every stage uses (no stage writes an offset of its own):
///  - a vertex (geometry's clip and screen vertices): every row present, in enum order, `floats` in all; the
///    first `clipped_floats` (every row before depth) are what clipping interpolates;
///  - a triangle record's attribute floats: the flat rows once (`flat_floats`), then per vertex k the
///    interpolated rows (`stride` floats each, vertex k's at flat_floats + k stride).
struct VaryingLayout {
  /// Every row: the sum of kVaryingWidth (14), computed so that a new row or width cannot leave it behind.
  static constexpr int kMaxFloats = kVaryingFloats;
  Interpolation interpolation[kVaryingCount] = {};
  std::int8_t vertex_offset[kVaryingCount] = {0, -1, -1, -1, -1, -1};  ///< in a vertex's floats; -1: absent
  std::int8_t record_offset[kVaryingCount] = {0,  -1, -1, -1,
                                              -1, -1};  ///< flat: in the record; else in a vertex's stride
  std::uint8_t floats = 4, clipped_floats = 4, flat_floats = 4, stride = 0;

  static VaryingLayout of(Varyings varyings);
  bool has(Varying v) const { return vertex_offset[static_cast<int>(v)] >= 0; }
  Interpolation how(Varying v) const { return interpolation[static_cast<int>(v)]; }
  /// Where vertex k's value of `v` starts in a record's attribute floats (the same k for a flat row).
  int record_at(Varying v, int k) const {
    const int i = static_cast<int>(v);
    return interpolation[i] == Interpolation::flat ? record_offset[i]
                                                   : flat_floats + k * stride + record_offset[i];
  }
  int record_floats() const { return flat_floats + 3 * stride; }
};

/// How one primitive's triangles or lines are drawn.
struct PrimitivePlan {
  bool smooth = false;  ///< colour per pixel (interpolated colours, textures, per-pixel light); false: one
                        ///< colour per face
  bool blend = false;   ///< some colour has alpha < 255: source-over blending; false: plain stores
  bool depth = false;   ///< 3D: depth-tested and depth-written; 2D overlays are not
  bool lit = false;     ///< 3D: Lambert lighting (flat: once per face; smooth: per pixel)
  bool compute_normals = false;  ///< per-pixel lighting of a mesh without normals: computed, angle-weighted
  /// With compute_normals, a mesh of more triangles than the image has pixels (most of which draw nothing):
  /// the triangles that may draw are found first, and only their corners' normals are computed (each still
  /// the sum of all its faces: the same bits as every vertex's).
  bool normals_where_drawn = false;
  /// 3D textured: some texel of the mesh's textures has alpha 0 (glTF's MASK cut-outs). Its pixels are shaded
  /// before their depth is written, and one whose alpha comes out 0 writes neither colour nor depth, so what
  /// is drawn later behind a cut-out shows through it. Found once per texture by the plan; meshes without
  /// such texels keep the path that writes depth first.
  bool cut_outs = false;
  /// 3D: some face has a specular material (scene.h: Material::is_specular): lit per pixel, with the world
  /// position row for the view direction, and a draw call per material. False: Lambert alone, as before.
  bool specular = false;
  /// Specular faces of a flat-shaded mesh: the normal row holds each face's own normal at its three
  /// corners (faceted, while the highlight still moves across the face with the view direction).
  bool face_normals = false;
  bool line_rectangles =
      false;  ///< 2D lines: drawn as rectangles of their width (anti-aliased or width != 1)
  /// 2D lines drawn as rectangles in one colour, every corner within the fast range (setup.h): each segment
  /// is one four-edge record, not two triangles sharing a diagonal.
  bool line_quads = false;
  /// Area coverage: the primitive's triangles and quads (a line's two triangles, a polyline's segments) add
  /// up their coverage of each pixel, at most 1, and the primitive is composited once: no seam along a
  /// rectangle's diagonal, no darker joints where translucent segments overlap. Not needed, so not planned,
  /// for a single segment drawn as one quad.
  bool union_coverage = false;
  /// What its vertices carry (colour always; normals, texture coordinates, positions, depth as it needs).
  /// Colours vary (2D: affine; 3D: perspective) or are flat; lit per pixel means a normal row.
  Varyings varyings;
  friend bool operator==(const PrimitivePlan&, const PrimitivePlan&) = default;
};

/// One visible primitive and how it is drawn. Primitives whose bounding box misses the image, and meshes
/// with nothing to draw, have none (they are culled here, before geometry).
struct DrawPlan {
  std::uint32_t primitive = 0;  ///< index into Scene::primitives
  PrimitivePlan mode;           ///< its triangles, or its 2D lines
  PrimitivePlan line_mode;      ///< meshes: its segments and wireframe edges (aliased, depth-tested)
  PrimitivePlan edge_mode;      ///< meshes with "edges": the feature edges (depth-tested, one colour)
  PrimitivePlan point_mode;     ///< meshes with points: depth-tested, unlit, one colour a point (depth set
                                ///< exactly when the mesh has points)
  std::int32_t shader = -1;     ///< shader primitives: index into RenderPlan::shaders
};

/// A shader primitive as the render runs it: its compiled program, the pixels it writes and every uniform
/// slot's bits, all resolved once (plan/shaders.cpp).
struct ShaderPlan {
  std::uint32_t primitive = 0;  ///< index into Scene::primitives
  std::shared_ptr<const CompiledShader> shader;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< pixels it writes, [x0, x1) x [y0, y1): its rectangle in the image
  /// Its rectangle, pixels, origin top-left, y down: fragCoord is measured from its bottom-left corner, and
  /// iResolution is its size.
  int rect_x = 0, rect_y = 0, rect_width = 0, rect_height = 0;
  /// The bits of every slot of every uniform the program reads: (slot, bits), written before its prologue.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> uniforms;
  std::array<std::int32_t, 4> channels{-1, -1, -1, -1};  ///< per iChannel it samples: an index into the
                                                         ///< primitive's textures; -1: none (reads zero)
  bool opaque = true;  ///< its colour replaces the pixel's; false: composited source-over by its alpha
  int samples = 1;     ///< evaluations a pixel (multisampled renders: the plan's samples, averaged)
  std::int64_t max_iterations =
      0;  ///< loop iterations a pixel may take (Limits::shader), every loop together
  std::int64_t register_bytes = 0;  ///< one thread's register file for it: slots x 64 lanes x 4 bytes
};

/// One light resolved for this view: camera-space lights turned into world space, colour x intensity folded.
struct LightPlan {
  LightKind kind = LightKind::ambient;
  Vec3 to_light;              ///< directional: unit world vector pointing toward the light
  Vec3 position;              ///< point: world position
  double rgb[3] = {0, 0, 0};  ///< colour x intensity per channel, >= 0
};

/// The camera after fitting, and the light: everything geometry needs to go from world to clip space.
/// Clip space: x, y in [-w, w] (y up), and reversed depth z in [0, w]: z / w is 1 at the near plane and
/// falls toward 0 at the far plane, which spreads float precision evenly over distance.
struct ViewPlan {
  Projection projection = Projection::perspective;
  Vec3 eye, target, up;           ///< world
  double fov_deg = 45;            ///< vertical, degrees
  double near = 1, far = 2;       ///< distances from the eye along the view direction
  double height = 0;              ///< orthographic: world units visible vertically
  Mat4 world_to_clip;             ///< projection * view
  std::vector<LightPlan> lights;  ///< the scene's lights (or the default ones) in world space
};

/// Floats a pixel of area-coverage accumulation holds (union primitives): the summed share, then the sums of
/// share x R, G, B, A (0..255 scale).
inline constexpr int kUnionFloats = 5;

/// One render thread's tile storage, in the units it is allocated in: the plan works these out once and
/// the framebuffer allocates exactly them (framebuffer/tiles.h). Every buffer is a whole tile
/// (RenderPlan::tile_width() x tile_height() pixels); a size is 0 when the render does not use the buffer.
struct TileStoragePlan {
  std::int64_t pixels = 0;           ///< tile_width() x tile_height(), a multiple of 64 (whole 8x8 blocks)
  std::int64_t color_bytes = 0;      ///< channels a pixel; 0 when tiles draw in place
  std::int64_t depth_floats = 0;     ///< a float a sample (reversed z / w); 0 without 3D content
  std::int64_t sample_bytes = 0;     ///< multisampling: channels a sample
  std::int64_t coverage_floats = 0;  ///< area coverage with union primitives: kUnionFloats a pixel
  std::int64_t expanded_words = 0;   ///< a bit a pixel in 64-bit words (one per 8x8 block), with samples
                                     ///< or union coverage: which pixels' samples differ / were accumulated
};

/// Bytes of pixel storage each buffer will take, over all threads; checked against the limits before
/// allocation. The per-thread buffers are RenderPlan::threads times RenderPlan::tile_storage.
struct MemoryPlan {
  std::int64_t color_bytes = 0;   ///< the colour buffer, which is also the output Image
  std::int64_t depth_bytes = 0;   ///< depth: one tile's per thread (4 bytes a sample); 0 for 2D scenes
  std::int64_t sample_bytes = 0;  ///< multisampling: each thread's tile of colour per sample, plus a bit per
                                  ///< pixel saying whether its samples differ; 0 unless the plan multisamples
  std::int64_t tile_bytes = 0;    ///< each thread's tile of colour, where a tile is drawn before it is copied
                                  ///< out; 0 when tiles draw in place (RenderPlan::tiles_in_place)
  std::int64_t coverage_bytes = 0;  ///< area coverage: each thread's tile of summed coverage and colour (5
                                    ///< floats and a bit a pixel), when some primitive has union_coverage
  std::int64_t texture_bytes = 0;   ///< textures of textured meshes: their decoded texels (held by the scene)
                                    ///< plus the mipmaps each render makes of them
  std::int64_t edge_bytes = 0;      ///< "antialias": "auto": the edge pixels' masks (8 bytes per 8x8 block of
                                    ///< the image) and a row of the quads' differences (a byte per channel)
  /// Shaders: each thread's register file for each program (ShaderPlan::register_bytes), and the mipmaps of
  /// the images their channels sample (the images themselves are texture_bytes).
  std::int64_t shader_bytes = 0;
  std::int64_t total() const {
    return color_bytes + depth_bytes + sample_bytes + tile_bytes + coverage_bytes + texture_bytes +
           edge_bytes + shader_bytes;
  }
};

/// PNG settings: the colour type follows the pixel format (0 grey, 4 grey+alpha, 2 RGB, 6 RGBA). Rows are
/// always filtered with "Up" (see png.cpp for the measurement).
struct PngPlan {
  int color_type = 2;  ///< PNG IHDR colour type
  /// igzip (ISA-L) level, 0 (fastest) .. 3 (smallest); 1 is the fastest whose files stay smaller than
  /// stb_image_write's on the benchmark scenes (docs/performance.md).
  int deflate_level = 1;
};

/// The PNG settings for a pixel format: its colour type, and the default deflate level.
PngPlan png_plan_for(PixelFormat format);

/// How a triangle's pixels are covered; the one choice every tile obeys.
enum class Coverage : std::uint8_t {
  centre,   ///< aliased: a pixel is covered when its centre is (top-left rule for centres on an edge)
  samples,  ///< multisampling: at each of RenderPlan::samples positions of the standard pattern
  area,     ///< exact area: the share of the pixel's square (2D scenes with "antialias": "area")
  /// "antialias": "auto": every tile drawn aliased; then the 8x8 blocks where a pixel differs from a
  /// neighbour (shade/edges.h) drawn again multisampled at RenderPlan::samples, from the same records
  edge_samples,
};

/// Whether `coverage` multisamples somewhere: its records are set up for, and its tiles keep, samples.
constexpr bool multisampled(Coverage coverage) {
  return coverage == Coverage::samples || coverage == Coverage::edge_samples;
}

/// Which instruction set the pixel kernels use. SSE2 is the x86-64 floor (and what other machines' generic
/// vector code stands for); AVX2 kernels exist for the hottest loops and give the same bytes.
enum class Simd : std::uint8_t { sse2, avx2 };

/// The widest Simd this machine runs.
Simd best_simd();

struct RenderPlan {
  int width = 0;                           ///< pixels
  int height = 0;                          ///< pixels
  PixelFormat format = PixelFormat::rgb8;  ///< fewest channels that hold every colour the render can make
  bool depth_buffer = false;               ///< only 3D content needs one; 2D never does
  Coverage coverage = Coverage::centre;    ///< how triangles cover pixels
  int samples = 1;                         ///< per pixel: > 1 exactly when coverage multisamples
  std::vector<DrawPlan> draws;             ///< the visible primitives, in scene order
  std::vector<ShaderPlan> shaders;         ///< the visible shader primitives' programs, in scene order

  // Counts of the per-primitive decisions, for the explain output and the X-Render-Plan header.
  std::int64_t flat_count = 0;      ///< visible primitives drawn with one colour
  std::int64_t shader_count = 0;    ///< visible shader primitives
  std::int64_t smooth_count = 0;    ///< visible primitives with interpolated colours
  std::int64_t blend_count = 0;     ///< visible primitives that blend
  std::int64_t culled_count = 0;    ///< primitives skipped before setup
  std::int64_t lit_count = 0;       ///< meshes lit by the light
  std::int64_t triangles_3d = 0;    ///< triangles of all visible meshes (before clipping)
  std::int64_t points_3d = 0;       ///< points of all visible meshes (before clipping)
  std::int64_t textured_count = 0;  ///< meshes drawn with textures

  ViewPlan view;  ///< meaningful only when depth_buffer is true (the scene has 3D content)

  std::int64_t work = 0;  ///< estimated pixel writes that threads split: each visible primitive's clipped box
  int threads = 1;  ///< 1: everything on the calling thread, no hand-off; >1: that many threads take tiles
  /// Tile side in pixels, a multiple of 8: records are binned to tiles and threads take tiles. Small scenes
  /// get one tile as large as the image (binning them costs more than it saves).
  int tile = 64;
  /// Tiles draw straight into the image, with no storage of their own and no copies: 2D, aliased, and the
  /// image whole blocks wide (kernels may rewrite a block row's other pixels unchanged, which must be the
  /// same tile's). Otherwise each thread draws a tile in its own storage, filled from the image and copied
  /// back.
  bool tiles_in_place = false;
  bool scalar_coverage = false;  ///< test hook: partial blocks tested one pixel at a time, not in SIMD lanes
  bool scalar_shading = false;   ///< test hook: programs run by the scalar reference, one lane at a time
  /// Test hook: multisampled pixels keep a colour per sample from the start, where the storage keeps one
  /// colour a pixel until its samples differ; the bytes must not change.
  bool keep_samples = false;
  Simd simd = Simd::sse2;        ///< the kernels' instruction set: the machine's best unless limited
  TileStoragePlan tile_storage;  ///< what each thread allocates for its tiles (`memory` counts it per thread)
  MemoryPlan memory;
  PngPlan png;

  /// Pixels a side of a thread's tile storage: the widest (tallest) tile, rounded up to whole 8x8 blocks so
  /// a block never reaches past it.
  int tile_width() const { return tile < width ? tile : (width + 7) / 8 * 8; }
  int tile_height() const { return tile < height ? tile : (height + 7) / 8 * 8; }

  /// The draw of scene primitive `index`, or nullptr when it was culled.
  const DrawPlan* draw_of(std::uint32_t index) const;
};

/// Execution knobs that are the caller's, not the scene's.
struct PlanOptions {
  int max_threads = 0;           ///< 0: the machine's core count; 1: never leave the calling thread
  int tile = 0;                  ///< 0: the plan's choice; else the tile side (rounded up to a multiple of 8)
  bool scalar_coverage = false;  ///< test hook, see RenderPlan::scalar_coverage
  bool keep_samples = false;     ///< test hook, see RenderPlan::keep_samples
  Simd max_simd = Simd::avx2;    ///< the widest kernels to use (tests force each one the machine has)
  bool scalar_shading = false;   ///< test hook, see RenderPlan::scalar_shading
  /// Optional: compiled programs by source, kept between renders (a service's); null: each render compiles.
  ShaderCache* shader_cache = nullptr;
};

/// Makes the plan. Throws SceneError(limit) when its memory or size exceeds `limits`.
RenderPlan plan(const Scene& scene, const Limits& limits = {}, const PlanOptions& options = {});

/// The plan as a JSON document (for `--explain` and `?explain=1`).
std::string explain_json(const RenderPlan& plan);

/// One short line, e.g. "rgb8 depth=none samples=1 flat=812 smooth=4 blend=0 culled=0 threads=1".
std::string explain_line(const RenderPlan& plan);

}  // namespace raster
