#include "coverage/point.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "framebuffer/pixel.h"

namespace raster::detail {
namespace {

// Squared distance from the point's centre to the position (at.x, at.y) of pixel (x, y), in (1/256 px)^2.
// Exact: the box lies within the guard band, so every term fits easily in 64 bits.
inline std::int64_t distance2(const PointRecord& p, int x, int y, SamplePoint at) {
  const std::int64_t dx = std::int64_t{x} * kSubpixelScale + at.x - p.x;
  const std::int64_t dy = std::int64_t{y} * kSubpixelScale + at.y - p.y;
  return dx * dx + dy * dy;
}

template <int C>
void draw_centres(const PointRecord& p, const PrimitivePlan& mode, const Surface& s, Rect r) {
  const SamplePoint centre{kSubpixelScale / 2, kSubpixelScale / 2};
  const std::int64_t radius2 = p.radius * p.radius;
  std::int64_t shaded = 0;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) {
      if (distance2(p, x, y, centre) > radius2) continue;
      const std::size_t index = s.index(x, y);
      if (mode.depth) {  // reversed: larger is nearer; ties keep what was drawn first
        if (!(p.depth > s.depth[index])) continue;
        s.depth[index] = p.depth;
      }
      put<C>(s.color + index * C, p.color, mode.blend);
      ++shaded;
    }
  if (s.shaded) *s.shaded += shaded;
}

// Multisampling: each sample of a pixel tested against the disc and its own depth plane; a pixel all of
// whose samples take the point's colour holds it once again, others keep a colour per sample (as the
// triangle shader's samples do, framebuffer/surface.h).
template <int C>
void draw_samples(const PointRecord& p, const PrimitivePlan& mode, const Surface& s, Rect r) {
  const int n = s.sample_count;
  const unsigned all = (1u << n) - 1;
  const std::int64_t radius2 = p.radius * p.radius;
  std::int64_t shaded = 0;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) {
      const std::size_t index = s.index(x, y);
      unsigned passed = 0;
      for (int k = 0; k < n; ++k) {
        if (distance2(p, x, y, s.pattern[k]) > radius2) continue;
        if (mode.depth) {
          float& stored = s.depth[static_cast<std::size_t>(k) * s.plane + index];
          if (!(p.depth > stored)) continue;
          stored = p.depth;
        }
        passed |= 1u << k;
      }
      if (!passed) continue;
      ++shaded;
      const int bx = x - (x - s.x0) % 8, by = y - (y - s.y0) % 8;
      std::uint64_t& expanded = s.expanded_bits(bx, by);
      const std::uint64_t bit = std::uint64_t{1} << (8 * ((y - s.y0) % 8) + (x - s.x0) % 8);
      if (passed == all && !mode.blend) {
        store<C>(s.color + index * C, p.color);
        s.one_colour<C>(expanded, bx, by, bit);
        continue;
      }
      if (!(expanded & bit)) {
        if (passed == all) {  // blending over a pixel whose samples agree: still one colour
          blend<C>(s.color + index * C, p.color);
          continue;
        }
        s.expand<C>(index);
        expanded |= bit;
      }
      for (unsigned m = passed; m; m &= m - 1)
        put<C>(s.sample_pixel<C>(std::countr_zero(m), index), p.color, mode.blend);
    }
  if (s.shaded) *s.shaded += shaded;
}

template <int C>
void draw_point_in(const PointRecord& p, const PrimitivePlan& mode, const Surface& s, Rect r) {
  // Area coverage never reaches here: a scene with 3D content is multisampled instead (the plan).
  if (s.coverage_mode == Coverage::samples)
    draw_samples<C>(p, mode, s, r);
  else
    draw_centres<C>(p, mode, s, r);
}

}  // namespace

void draw_point(const PointRecord& point, const PrimitivePlan& mode, const Surface& surface, Rect clip,
                StopMeter& meter) {
  const Rect r{std::max(clip.x0, point.box.x0), std::max(clip.y0, point.box.y0),
               std::min(clip.x1, point.box.x1), std::min(clip.y1, point.box.y1)};
  if (r.empty()) return;
  switch (surface.channels) {
    case 1:
      draw_point_in<1>(point, mode, surface, r);
      break;
    case 2:
      draw_point_in<2>(point, mode, surface, r);
      break;
    case 3:
      draw_point_in<3>(point, mode, surface, r);
      break;
    default:
      draw_point_in<4>(point, mode, surface, r);
      break;
  }
  meter.add(std::int64_t{r.x1 - r.x0} * (r.y1 - r.y0));
}

}  // namespace raster::detail
