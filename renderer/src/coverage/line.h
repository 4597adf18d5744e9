// Line: 1-px line records -> pixels of one tile, by clipped, symmetric Bresenham (the rule GPUs use for
// aliased lines: one pixel per column or row of the major axis, in the row nearest the exact line).
// Wide and anti-aliased lines are not drawn here: setup makes their rectangles four-edge quad records (or
// two triangle records) for the block walker.
#pragma once

#include "base/stop.h"
#include "framebuffer/surface.h"
#include "raster/image.h"
#include "setup/setup.h"

namespace raster::detail {

/// Draws `line` into the pixels of `surface` inside `clip` (image coordinates, within the surface); 3D
/// lines (mode.depth) also test and write its depth. Counts its work on `meter` (at most one pixel per column
/// or row of the clip).
void draw_line(const LineRecord& line, const PrimitivePlan& mode, const Surface& surface, Rect clip,
               StopMeter& meter);

}  // namespace raster::detail
