// Geometry: Scene + RenderPlan -> DrawList, screen-space primitives ready for coverage. Triangle vertices
// are snapped to 1/256 px; line endpoints become the pixels that contain them. Nothing here touches pixels
// and nothing is approximated: geometry far outside the image takes an exact wide-integer path instead of
// being clipped in floating point.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/plan.h"
#include "raster/scene.h"

namespace raster::detail {

inline constexpr int kSubpixelBits = 8;                              ///< GPU-style 8 sub-pixel bits
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
  bool draw_first = true;  ///< false: endpoint 0's pixel belongs to the previous polyline segment
  bool draw_last = true;   ///< false: endpoint 1's pixel belongs to the next segment (closing segment)
};

/// One scene primitive after geometry: a run of records of one kind, drawn with one PrimitivePlan.
struct DrawOp {
  enum class Kind : std::uint8_t { triangles, huge_triangles, lines } kind = Kind::triangles;
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
};

/// Builds the draw list of the plan's visible primitives.
DrawList build_draw_list(const Scene& scene, const RenderPlan& plan);

/// Snaps a coordinate (pixels) to an integral number of 1/256 px, rounding half up, so that translating by
/// whole pixels translates the result exactly.
double snap(double px);

}  // namespace raster::detail
