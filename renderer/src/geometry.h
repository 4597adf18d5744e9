// Geometry: Scene + RenderPlan -> DrawList, screen-space primitives in fixed point, ready for coverage.
// Triangles are clipped to a guard band and snapped to 1/256 px; lines become integer pixel endpoints
// in a canonical order. Nothing here touches pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/plan.h"
#include "raster/scene.h"

namespace raster::detail {

inline constexpr int kSubpixelBits = 8;                    ///< GPU-style 8 sub-pixel bits
inline constexpr std::int64_t kSubpixelScale = 1 << kSubpixelBits;  ///< fixed-point units per pixel

/// Triangles are clipped to [-kGuardBandPx, kGuardBandPx]^2 before snapping, so every snapped coordinate
/// fits in 24 bits and every edge-function product in 49 bits: int64 evaluation cannot overflow.
/// The guard band is twice the largest image side, so its edges never touch a visible pixel.
inline constexpr double kGuardBandPx = 2.0 * kMaxImageSide;

/// Lines keep their exact integer pixel endpoints while both lie within +-kLineRangePx; a longer line is
/// first cut to that box along its real-valued segment (a change far below a pixel inside the image).
inline constexpr double kLineRangePx = 1073741824.0;  // 2^30

/// A triangle vertex ready for coverage.
struct ScreenVertex {
  std::int32_t x = 0, y = 0;  ///< 1/256 px, origin top-left, y down; |x|, |y| < 2^23
  Rgba8 color;
};

struct ScreenTriangle {
  ScreenVertex v[3];  ///< either winding; coverage normalizes it
};

/// A 1-px line between the centres of two pixels, in canonical order: along its major axis (x when
/// |dx| >= |dy|, else y) the first endpoint has the smaller coordinate, so a->b and b->a are the same
/// record and therefore the same pixels.
struct ScreenLine {
  std::int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< pixel indices (column, row); |value| <= 2^30
  Rgba8 c0, c1;            ///< colours at the first and last endpoint
  bool draw_first = true;  ///< false: the first pixel belongs to the previous polyline segment
  bool draw_last = true;   ///< false: the last pixel belongs to the next segment (closing segment)
};

/// One scene primitive after geometry: a run of triangles or of lines, drawn with one PrimitivePlan.
struct DrawOp {
  enum class Kind : std::uint8_t { triangles, lines } kind = Kind::triangles;
  PrimitivePlan mode;
  std::uint32_t first = 0;  ///< index into DrawList::triangles or DrawList::lines
  std::uint32_t count = 0;
};

/// Everything the raster stage draws, in scene order.
struct DrawList {
  std::vector<DrawOp> ops;
  std::vector<ScreenTriangle> triangles;
  std::vector<ScreenLine> lines;
};

/// Builds the draw list of the plan's visible primitives.
DrawList build_draw_list(const Scene& scene, const RenderPlan& plan);

/// Snaps a guard-band coordinate (pixels) to 1/256 px, rounding half up so that translating by whole
/// pixels translates the result exactly.
std::int32_t snap(double px);

}  // namespace raster::detail
