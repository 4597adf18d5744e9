// The plan stage: every "does this scene need X" decision, made once, from the scene alone.
#include "raster/plan.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include <nlohmann/json.hpp>

namespace raster {
namespace {

// Below this much estimated work (bounding-box pixels touched by visible primitives; clearing is not
// split, so it does not count) a render stays on the calling thread. bench/parallel_threshold measured two
// bands 1.30x slower at 5.6e4 and 0.82x at 1.1e5 for smooth triangles (crossover ~8.5e4; flat fills cost
// less per pixel, so theirs is higher); see docs/performance.md.
constexpr std::int64_t kParallelWorkThreshold = 100'000;
// Small scenes never leave the calling thread, whatever their estimate: no hand-off for a thumbnail.
constexpr std::int64_t kSmallScenePixels = 256 * 256;
constexpr std::size_t kSmallScenePrimitives = 100;
// A band shorter than this spends more on per-band triangle setup than it gains.
constexpr int kMinBandRows = 16;

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

void check_references(const Scene& scene) {
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& p = scene.primitives[i];
    const std::size_t colors = p.per_vertex_color ? p.point_count : 1;
    const bool ok = std::size_t{p.first_point} + p.point_count <= scene.points.size() &&
                    std::size_t{p.first_color} + colors <= scene.colors.size() &&
                    p.point_count == (p.kind == PrimitiveKind::triangle ? 3u : p.kind == PrimitiveKind::line ? 2u : std::max(p.point_count, 2u));
    if (!ok)
      throw SceneError(ErrorKind::invalid, "primitive refers to points or colours the scene does not have",
                       {"/primitives/" + std::to_string(i), 0, 0});
  }
  // Scenes built in code skip the parser's checks; coverage relies on these bounds.
  for (std::size_t i = 0; i < scene.points.size(); ++i) {
    const Point2& q = scene.points[i];
    if (!(std::fabs(q.x) <= kMaxCoordinate && std::fabs(q.y) <= kMaxCoordinate))
      throw SceneError(ErrorKind::invalid, "point " + std::to_string(i) + " is not finite or outside +-2^128");
  }
}

void check_size(const Scene& scene, const Limits& limits) {
  const int max_w = std::min(limits.max_width, kMaxImageSide), max_h = std::min(limits.max_height, kMaxImageSide);
  if (scene.width < 1 || scene.height < 1)
    throw SceneError(ErrorKind::invalid, "image size must be at least 1x1");
  if (scene.width > max_w || scene.height > max_h ||
      std::int64_t{scene.width} * scene.height > limits.max_pixels)
    throw SceneError(ErrorKind::limit, std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                                           " exceeds the image size limits");
  if (static_cast<std::int64_t>(scene.primitives.size()) > limits.max_primitives)
    throw SceneError(ErrorKind::limit, "too many primitives", {"/primitives", 0, 0});
}

const char* format_name(PixelFormat f) {
  switch (f) {
    case PixelFormat::grey8: return "grey8";
    case PixelFormat::grey_alpha8: return "grey_alpha8";
    case PixelFormat::rgb8: return "rgb8";
    case PixelFormat::rgba8: return "rgba8";
  }
  return "?";
}

int png_color_type(PixelFormat f) {
  switch (f) {
    case PixelFormat::grey8: return 0;
    case PixelFormat::grey_alpha8: return 4;
    case PixelFormat::rgb8: return 2;
    case PixelFormat::rgba8: return 6;
  }
  return 2;
}

}  // namespace

RenderPlan plan(const Scene& scene, const Limits& limits, const PlanOptions& options) {
  check_size(scene, limits);
  check_references(scene);

  RenderPlan out;
  out.width = scene.width;
  out.height = scene.height;
  out.primitives.resize(scene.primitives.size());

  const double w = scene.width, h = scene.height;
  const std::int64_t image_pixels = std::int64_t{scene.width} * scene.height;
  bool grey = scene.background.is_grey();
  const bool alpha = !scene.background.is_opaque();  // drawing over an opaque background stays opaque
  std::int64_t work = 0;

  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& prim = scene.primitives[i];
    PrimitivePlan& pp = out.primitives[i];
    const Box b = bounds(scene, prim);
    // Conservative: a primitive touching the image's closed rectangle is kept.
    pp.visible = b.x1 >= 0 && b.x0 <= w && b.y1 >= 0 && b.y0 <= h;
    if (!pp.visible) {
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
    (pp.smooth ? out.smooth_count : out.flat_count) += 1;
    out.blend_count += pp.blend ? 1 : 0;
    const double cw = std::min(b.x1, w) - std::max(b.x0, 0.0) + 1, ch = std::min(b.y1, h) - std::max(b.y0, 0.0) + 1;
    const bool filled = prim.kind == PrimitiveKind::triangle && prim.fill;
    work += static_cast<std::int64_t>(filled ? cw * ch : std::max(cw, ch));
  }

  out.format = grey ? (alpha ? PixelFormat::grey_alpha8 : PixelFormat::grey8)
                    : (alpha ? PixelFormat::rgba8 : PixelFormat::rgb8);
  out.memory.color_bytes = image_pixels * channel_count(out.format);
  if (out.memory.total() > limits.max_buffer_bytes)
    throw SceneError(ErrorKind::limit, "the render needs " + std::to_string(out.memory.total()) +
                                           " bytes of pixel storage, over the limit of " +
                                           std::to_string(limits.max_buffer_bytes));

  const int cores = options.max_threads > 0 ? options.max_threads
                                            : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  out.work = work;
  const bool small = image_pixels <= kSmallScenePixels && scene.primitives.size() <= kSmallScenePrimitives;
  out.threads = small || work < kParallelWorkThreshold ? 1 : std::clamp(scene.height / kMinBandRows, 1, cores);
  out.png.color_type = png_color_type(out.format);
  return out;
}

std::string explain_json(const RenderPlan& p) {
  nlohmann::ordered_json j;
  j["width"] = p.width;
  j["height"] = p.height;
  j["format"] = format_name(p.format);
  j["channels"] = channel_count(p.format);
  j["depth_buffer"] = p.depth_buffer;
  j["samples"] = p.samples;
  j["primitives"] = {{"flat", p.flat_count}, {"smooth", p.smooth_count}, {"blend", p.blend_count}, {"culled", p.culled_count}};
  j["work"] = p.work;
  j["threads"] = p.threads;
  j["memory_bytes"] = {{"color", p.memory.color_bytes}, {"depth", p.memory.depth_bytes},
                       {"samples", p.memory.sample_bytes}, {"total", p.memory.total()}};
  j["png"] = {{"color_type", p.png.color_type}, {"deflate_level", p.png.deflate_level}};
  return j.dump(2);
}

std::string explain_line(const RenderPlan& p) {
  return std::string(format_name(p.format)) + " depth=" + (p.depth_buffer ? "f32" : "none") +
         " samples=" + std::to_string(p.samples) + " flat=" + std::to_string(p.flat_count) +
         " smooth=" + std::to_string(p.smooth_count) + " blend=" + std::to_string(p.blend_count) +
         " culled=" + std::to_string(p.culled_count) + " threads=" + std::to_string(p.threads);
}

}  // namespace raster
