// Geometry: Scene + RenderPlan -> DrawList, screen-space primitives ready for coverage. Triangle vertices
// are snapped to 1/256 px; line endpoints become the pixels that contain them. Nothing here touches pixels
// and nothing is approximated: geometry far outside the image takes an exact wide-integer path instead of
// being clipped in floating point.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/plan.h"
#include "raster/scene.h"
#include "stop.h"

namespace raster::detail {

inline constexpr int kSubpixelBits = 8;                             ///< GPU-style 8 sub-pixel bits
inline constexpr std::int64_t kSubpixelScale = 1 << kSubpixelBits;  ///< fixed-point units per pixel

/// Triangles whose vertices all lie within +-kFastRangePx take the int64 path: snapped coordinates fit in
/// 24 bits, so every edge-function product fits in 49 bits. Others take the exact wide path (wide.h).
inline constexpr double kFastRangePx = 32768.0;

/// A vertex of a fast-path triangle.
struct ScreenVertex {
  std::int32_t x = 0, y = 0;  ///< 1/256 px, origin top-left, y down; |x|, |y| <= 2^23
  Rgba8 color;
};

struct ScreenTriangle {
  ScreenVertex v[3];  ///< either winding; coverage normalizes it
};

/// A triangle with a vertex beyond kFastRangePx. Snapped coordinates are integers in 1/256 px held
/// exactly in doubles (|value| <= 2^136, see kMaxCoordinate).
struct HugeTriangle {
  double x[3] = {}, y[3] = {};  ///< 1/256 px, integral values
  Rgba8 color[3];
};

/// A 1-px line between the pixels that contain its endpoints. Pixel indices are integers held exactly in
/// doubles (|value| <= 2^128). Coverage orders the endpoints canonically, so a->b and b->a are the same.
struct ScreenLine {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< pixel column and row of each endpoint, integral values
  Rgba8 c0, c1;                           ///< colours at the two endpoints
  bool draw_first = true;        ///< false: endpoint 0's pixel belongs to the previous polyline segment
  bool draw_last = true;         ///< false: endpoint 1's pixel belongs to the next segment (closing segment)
  float depth0 = 0, depth1 = 0;  ///< 3D lines (ops with mode.depth): z / w at each endpoint, reversed
};

/// A vertex of a depth-tested (3D) triangle: snapped like ScreenVertex, plus what shading interpolates.
struct DepthVertex {
  std::int32_t x = 0, y = 0;  ///< 1/256 px, origin top-left, y down; within the guard band
  float depth = 0;            ///< z / w in [0, 1]: 1 at the near plane, toward 0 far away (reversed)
  float inv_w = 1;            ///< 1 / w, for perspective-correct interpolation
  float color[4] = {};        ///< straight RGBA, 0..255 (lighting already applied for flat shading)
  float normal[3] = {};       ///< world space, unit; used only for per-pixel lighting
};

struct DepthTriangle {
  DepthVertex v[3];
  bool back_facing = false;  ///< seen from behind: per-pixel lighting flips the normal (two-sided light)
};

/// One scene primitive after geometry: a run of records of one kind, drawn with one PrimitivePlan.
struct DrawOp {
  enum class Kind : std::uint8_t { triangles, huge_triangles, lines, depth_triangles } kind = Kind::triangles;
  PrimitivePlan mode;
  std::uint32_t first = 0;  ///< index into the DrawList vector of that kind
  std::uint32_t count = 0;
};

/// Everything the raster stage draws, in scene order.
struct DrawList {
  std::vector<DrawOp> ops;
  std::vector<ScreenTriangle> triangles;
  std::vector<HugeTriangle> huge_triangles;
  std::vector<ScreenLine> lines;
  std::vector<DepthTriangle> depth_triangles;
  double to_light[3] = {0, 0, 1};  ///< unit world vector toward the light (3D only)
  double ambient = 0.2;            ///< in [0, 1]
};

/// Builds the draw list of the plan's visible primitives. Stops early, with the list incomplete, once
/// `meter` says the render must stop (a record costs StopMeter::kPrimitiveWork).
DrawList build_draw_list(const Scene& scene, const RenderPlan& plan, StopMeter& meter);

/// The 3D part (geometry3d.cpp): a mesh through the plan's camera into depth triangles and 3D lines,
/// clipped in homogeneous space (near, far and a guard band) so that w > 0 everywhere and every snapped
/// coordinate stays in the fast range. Appends one op per kind it produces.
void add_mesh(const Mesh& mesh, const PrimitivePlan& mode, const RenderPlan& plan, DrawList& list,
              StopMeter& meter);

/// Snaps a coordinate (pixels) to an integral number of 1/256 px, rounding half up, so that translating by
/// whole pixels translates the result exactly.
double snap(double px);

}  // namespace raster::detail
