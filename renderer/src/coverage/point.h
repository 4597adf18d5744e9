// Point: round point records -> pixels of one tile. A point is a disc of constant depth, so it needs no edge
// functions and no attribute planes: each pixel (or sample) of its box is covered when it lies within the
// radius, depth-tested against that one depth and given the point's one colour. Not expanded into triangles:
// a million points would be millions of records.
#pragma once

#include "base/stop.h"
#include "framebuffer/surface.h"
#include "setup/setup.h"

namespace raster::detail {

/// Draws `point` into the pixels of `surface` inside `clip` (image coordinates, within the surface): aliased,
/// the pixels whose centre is in the disc; multisampled, per sample (depth-tested per sample, the pixel's
/// samples kept apart where they differ). Depth-tested and written when `mode.depth`; blended when
/// `mode.blend`. Counts its work on `meter` (the pixels of its box inside the clip).
void draw_point(const PointRecord& point, const PrimitivePlan& mode, const Surface& surface, Rect clip,
                StopMeter& meter);

}  // namespace raster::detail
