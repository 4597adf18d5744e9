// Plan: Scene -> RenderPlan, every decision about what this render needs, made once before any pixel work.
// The renderer and the encoder execute a plan; they decide nothing themselves.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "raster/image.h"
#include "raster/scene.h"

namespace raster {

/// How one primitive is drawn. A culled primitive is skipped before setup.
struct PrimitivePlan {
  bool visible = true;  ///< false: its bounding box misses the image (culled before setup)
  bool smooth =
      false;  ///< interpolate per-vertex values (colours; normals when lit); false: one colour per face
  bool blend = false;            ///< some colour has alpha < 255: source-over blending; false: plain stores
  bool depth = false;            ///< 3D: depth-tested and depth-written; 2D overlays are not
  bool lit = false;              ///< 3D: Lambert lighting (flat: once per face; smooth: per pixel)
  bool compute_normals = false;  ///< smooth lighting on a mesh without normals: computed, angle-weighted
  bool light_per_pixel =
      false;  ///< smooth lighting: normals interpolated and lit at every pixel (else per face)
  bool line_rectangles =
      false;  ///< 2D lines: drawn as rectangles of their width (anti-aliased or width != 1)
};

/// The camera after fitting, and the light: everything geometry needs to go from world to clip space.
/// Clip space: x, y in [-w, w] (y up), and reversed depth z in [0, w]: z / w is 1 at the near plane and
/// falls toward 0 at the far plane, which spreads float precision evenly over distance.
struct ViewPlan {
  Projection projection = Projection::perspective;
  Vec3 eye, target, up;      ///< world
  double fov_deg = 45;       ///< vertical, degrees
  double near = 1, far = 2;  ///< distances from the eye along the view direction
  double height = 0;         ///< orthographic: world units visible vertically
  Mat4 world_to_clip;        ///< projection * view
  Vec3 to_light;             ///< unit world vector pointing toward the light
  double ambient = 0.2;      ///< in [0, 1]
};

/// Bytes of pixel storage each buffer will take; checked against the limits before allocation.
struct MemoryPlan {
  std::int64_t color_bytes = 0;   ///< the colour buffer, which is also the output Image
  std::int64_t depth_bytes = 0;   ///< depth buffer; 0 for 2D scenes
  std::int64_t sample_bytes = 0;  ///< multisample storage; 0 unless antialias > 1
  std::int64_t total() const { return color_bytes + depth_bytes + sample_bytes; }
};

/// PNG settings: the colour type follows the pixel format (0 grey, 4 grey+alpha, 2 RGB, 6 RGBA). Rows are
/// always filtered with "Up" (see png.cpp for the measurement).
struct PngPlan {
  int color_type = 2;  ///< PNG IHDR colour type
  /// igzip (ISA-L) level, 0 (fastest) .. 3 (smallest); 1 is the fastest whose files stay smaller than
  /// stb_image_write's on the benchmark scenes (docs/performance.md).
  int deflate_level = 1;
};

struct RenderPlan {
  int width = 0;                           ///< pixels
  int height = 0;                          ///< pixels
  PixelFormat format = PixelFormat::rgb8;  ///< fewest channels that hold every colour the render can make
  bool depth_buffer = false;               ///< only 3D content needs one; 2D never does
  int samples = 1;                         ///< per pixel; 1 = aliased, no sample storage
  std::vector<PrimitivePlan> primitives;   ///< parallel to Scene::primitives

  // Counts of the per-primitive decisions, for the explain output and the X-Render-Plan header.
  std::int64_t flat_count = 0;    ///< visible primitives drawn with one colour
  std::int64_t smooth_count = 0;  ///< visible primitives with interpolated colours
  std::int64_t blend_count = 0;   ///< visible primitives that blend
  std::int64_t culled_count = 0;  ///< primitives skipped before setup
  std::int64_t lit_count = 0;     ///< meshes lit by the light
  std::int64_t triangles_3d = 0;  ///< triangles of all visible meshes (before clipping)

  ViewPlan view;  ///< meaningful only when depth_buffer is true (the scene has 3D content)

  std::int64_t work = 0;  ///< estimated pixel writes that bands split: each visible primitive's clipped box
  int threads = 1;  ///< 1: everything on the calling thread, no hand-off; >1: that many horizontal bands
  MemoryPlan memory;
  PngPlan png;
};

/// Execution knobs that are the caller's, not the scene's.
struct PlanOptions {
  int max_threads = 0;  ///< 0: the machine's core count; 1: never leave the calling thread
};

/// Makes the plan. Throws SceneError(limit) when its memory or size exceeds `limits`.
RenderPlan plan(const Scene& scene, const Limits& limits = {}, const PlanOptions& options = {});

/// The plan as a JSON document (for `--explain` and `?explain=1`).
std::string explain_json(const RenderPlan& plan);

/// One short line, e.g. "rgb8 depth=none samples=1 flat=812 smooth=4 blend=0 culled=0 threads=1".
std::string explain_line(const RenderPlan& plan);

}  // namespace raster
