// Setup: geometry's screen-space primitives -> one record per triangle or line, made once per render, and
// the tile bins that list, per tile and in scene order, the records that may touch it. Nothing after this
// stage recomputes an edge, a bounding box or an attribute's weights.
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <span>
#include <type_traits>
#include <vector>

#include "base/grid.h"
#include "base/memory.h"
#include "base/mip_chain.h"
#include "base/stop.h"
#include "base/wide.h"
#include "plan/light.h"
#include "raster/plan.h"
#include "raster/scene.h"

namespace raster::detail {

/// What a record is drawn with: the plan's decisions for its primitive plus the constants shading needs.
struct DrawCall {
  PrimitivePlan mode;
  VaryingLayout layout;  ///< mode.varyings laid out: what its records' attribute floats hold, and where
  /// 3D lighting: the view's lights (ViewPlan::lights) as shading reads them.
  LightRig lights;
  /// Textured modes: the texture its triangles sample (in Setup::textures), or nullptr for faces without one.
  const MipChain* texture = nullptr;
  /// Specular modes (PrimitivePlan::specular): its triangles' material; model lambert for faces without one.
  Specular specular;
  /// Shader primitives: index into RenderPlan::shaders; its one quad record covers the program's pixels.
  std::int32_t shader = -1;
};

/// A draw call for `mode`, lighting at its defaults.
inline DrawCall make_call(const PrimitivePlan& mode) {
  DrawCall call;
  call.mode = mode;
  return call;
}

/// A vertex of a triangle, snapped, with the values its call's varyings (PrimitivePlan::varyings) give it.
struct SetupVertex {
  double x = 0, y = 0;  ///< 1/256 px, integral values, origin top-left, y down (|value| <= 2^136)
  /// At VaryingLayout::vertex_offset, rows in Varying order. Not initialised: whoever makes a vertex writes
  /// every row its call has (a dense mesh makes three a triangle, and zeroing them cost more than filling
  /// them).
  float values[VaryingLayout::kMaxFloats];

  float* at(const VaryingLayout& v, Varying name) { return values + v.vertex_offset[static_cast<int>(name)]; }
};

/// Edge functions of one triangle (N = 3) or one convex quadrilateral (N = 4, a line segment's rectangle) on
/// the 1/256 px grid, in the shape's own integer type T (int64 for the fast range, Wide beyond):
/// E_k(X, Y) = a[k] X + b[k] Y + c[k] at the sample point (X, Y) in 1/256 px, with the top-left rule folded
/// into c (an edge that is not top or left has 1 subtracted), so a sample is covered exactly when all N are
/// >= 0. For a triangle E_k is vertex k's barycentric weight times `area`.
template <typename T, int N = 3>
struct EdgeFunctions {  // not scene.h's Edges (feature edges drawn over a mesh)
  /// In the fast range a and b are coordinate differences below 2^24: 32 bits hold them.
  using Coefficient = std::conditional_t<std::is_same_v<T, std::int64_t>, std::int32_t, T>;
  Coefficient a[N], b[N];
  T c[N];
  T area;  ///< twice the shape's area in 1/256 px units squared, > 0
};

/// One triangle, set up: its edges, the pixels it may touch, and its attributes in barycentric form.
/// Attributes are planes: any attribute v is the affine function sum_k E_k(X, Y) v_k / area, evaluated
/// from the exact edge values, so a pixel's value does not depend on which tile or block computes it.
struct TriangleRecord {
  static constexpr std::uint32_t kFast = ~0u;
  Rect box;  ///< pixels whose sample point may be covered, clipped to the image (first: binning reads it
             ///< alone)
  EdgeFunctions<std::int64_t> edges;  ///< the edges, when in the fast range (kept here: one fetch per record)
  std::uint32_t call = 0;             ///< index into Setup::calls
  std::uint32_t attributes =
      0;  ///< index into its part's attributes of this record's first float (VaryingLayout)
  std::uint32_t wide = kFast;  ///< kFast, or the index of its edges in Setup::wide_edges
  bool back_facing = false;    ///< 3D: seen from behind (per-pixel lighting flips the normal)
};

/// A segment of a flat-coloured 2D line drawn as its rectangle (plan.h: PrimitivePlan::line_quads): the
/// rectangle as one convex quadrilateral, its four edges walked by the triangles' block walker, where two
/// triangle records would share a diagonal that cuts nearly every pixel of a thin line twice. The same
/// snapped corners and edges as those two triangles, so aliased and multisampled lines keep their pixels.
struct QuadRecord {
  Rect box;  ///< pixels whose sample point (or square, for area and samples) it may cover, clipped to the
             ///< image
  EdgeFunctions<std::int64_t, 4> edges;  ///< edge k runs from corner k to corner k + 1, interior E > 0
  std::uint32_t call = 0;                ///< index into Setup::calls
  std::uint32_t attributes = 0;          ///< index into its part's attributes: the colour, as a flat row
};

/// A 1-px line between the pixels that contain its endpoints. Pixel indices are integers held exactly in
/// doubles (|value| <= 2^128). Coverage orders the endpoints canonically, so a->b and b->a are the same.
struct LineRecord {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< pixel column and row of each endpoint, integral values
  Rgba8 c0, c1;                           ///< colours at the two endpoints
  bool draw_first = true;        ///< false: endpoint 0's pixel belongs to the previous polyline segment
  bool draw_last = true;         ///< false: endpoint 1's pixel belongs to the next segment (closing segment)
  float depth0 = 0, depth1 = 0;  ///< 3D lines (mode.depth): z / w at each endpoint, reversed
  std::uint32_t call = 0;        ///< index into Setup::calls
  Rect box;                      ///< pixels it may touch, clipped to the image
};

/// A round point of a model (Mesh::points): a disc at the projected vertex, at one depth. A sample is covered
/// when its distance from the centre is at most the radius, decided exactly on the 1/256 px grid: the same
/// pixels in every tile and at every thread count.
struct PointRecord {
  std::int32_t x = 0, y = 0;  ///< the centre, 1/256 px, origin top-left, y down (inside the guard band)
  std::int64_t radius = 0;    ///< 1/256 px, >= 0 (at most 64 px / 2)
  float depth = 0;            ///< z / w, reversed (larger is nearer), the same over the whole disc
  Rgba8 color;                ///< straight RGBA: the vertex colour, unlit
  std::uint32_t call = 0;     ///< index into Setup::calls (depth test and blending)
  Rect box;                   ///< pixels it may touch, clipped to the image
};

/// A record in scene order: which kind and its index in that kind's array.
struct RecordRef {
  static constexpr std::uint32_t kLineBit = 1u << 31;
  static constexpr std::uint32_t kPointBit = 1u << 30;
  static constexpr std::uint32_t kKindBits = kLineBit | kPointBit;
  static constexpr std::uint32_t kQuadBits = kKindBits;  ///< both bits: a quad (test it before the others)
  /// Index into its part's triangles, or kLineBit | index into its part's lines, or kPointBit | index into
  /// its part's points, or kQuadBits | index into its part's quads (a part holds fewer than 2^30 records of a
  /// kind: a model's faces and points are limited far below that).
  std::uint32_t value = 0;
};

/// A run of records in scene order, with the storage they index. A setup is a sequence of parts so that the
/// triangles of a large mesh can be set up on every render thread at once, each thread filling its own
/// parts; the tiles draw the parts in order, so the image does not depend on how the work was split.
struct Records {
  PodArray<TriangleRecord> triangles;
  std::vector<EdgeFunctions<Wide>> wide_edges;  ///< TriangleRecord::wide indexes these
  PodArray<float> attributes;                   ///< TriangleRecord::attributes indexes these
  std::vector<LineRecord> lines;
  PodArray<PointRecord> points;
  PodArray<QuadRecord> quads;
  PodArray<RecordRef> order;  ///< every record of the part once, in the order the scene draws them

  /// Room for one more triangle record, made in place; drop_triangle() takes it back if it is not kept.
  TriangleRecord& grow_triangle() { return *triangles.grow(1); }
  void drop_triangle() { triangles.pop_back(); }
  /// Bytes its records hold (what is written of its arrays: room reserved and never written takes no
  /// memory, its pages never touched).
  std::int64_t bytes() const {
    return static_cast<std::int64_t>(triangles.size() * sizeof(TriangleRecord) +
                                     wide_edges.size() * sizeof(EdgeFunctions<Wide>) +
                                     attributes.size() * sizeof(float) + lines.size() * sizeof(LineRecord) +
                                     points.size() * sizeof(PointRecord) + quads.size() * sizeof(QuadRecord) +
                                     order.size() * sizeof(RecordRef));
  }
  /// Asks `stop`'s budget for what the records have grown by since `asked` bytes were asked, once that is
  /// kRenderRecordStep or more (or whatever it is, when `all`). False when refused: the render stops.
  bool account(const Stop& stop, std::int64_t& asked, bool all = false) const {
    const std::int64_t grown = bytes() - asked;
    if (grown <= 0 || (!all && grown < cost::kRenderRecordStep)) return true;
    asked += grown;
    return stop.reserve(grown);
  }
};

/// A triangle in the fast range, snapped (1/256 px, either winding), before its record exists.
struct FastTriangle {
  std::int64_t x[3], y[3];
};

/// Everything the tiles draw, in scene order.
struct Setup {
  std::vector<DrawCall> calls;
  std::vector<Records> parts;     ///< in scene order; a part's records all follow the previous part's
  std::deque<MipChain> textures;  ///< the mip chains textured calls sample (a deque: calls point into it)
  int width = 0, height = 0;      ///< the image, pixels
  /// The plan's coverage samples each pixel at its centre only (no multisampling, no area): boxes hold the
  /// pixels whose centre they contain, and a triangle that covers no centre gets no record.
  bool centre_samples = false;
  /// Multisampling: the positions each pixel is sampled at (sample_pattern), `pattern_size` of them; a small
  /// triangle that covers none of its box's samples gets no record. Null otherwise.
  const SamplePoint* pattern = nullptr;
  int pattern_size = 0;

  /// Adds a draw call (its layout made from its mode's varyings); returns its index.
  std::uint32_t add_call(const DrawCall& call);
  /// The part records are appended to (a new one when there is none).
  Records& last_part() { return parts.empty() ? parts.emplace_back() : parts.back(); }
  /// Sets up a triangle from three snapped vertices into `part`; degenerate ones and ones that miss the
  /// image are not added. Its attributes are the vertices' values of `call`'s varyings. Reads only the
  /// setup's calls and image: threads may fill different parts at once.
  void add_triangle(Records& part, std::uint32_t call, const SetupVertex (&v)[3],
                    bool back_facing = false) const;
  void add_triangle(std::uint32_t call, const SetupVertex (&v)[3], bool back_facing = false) {
    add_triangle(last_part(), call, v, back_facing);
  }
  /// The record of a fast-range triangle, its vertices put in the order of positive area (`order[k]` is the
  /// given vertex that became vertex k); false when it has no area or can cover nothing of the image. The
  /// caller appends it with its attributes in that order (as add_triangle does).
  bool fast_record(const FastTriangle& t, TriangleRecord& r, int (&order)[3]) const;
  /// Appends `r` (from fast_record, or with its edges and box set) to `part` with the attributes of `call`'s
  /// varyings taken from `v`, already in the record's vertex order.
  void append(Records& part, const TriangleRecord& r, std::uint32_t call, const SetupVertex* const (&v)[3],
              bool back_facing) const;
  /// The same for a record already made in place as the last of `part.triangles` (by fast_record into
  /// Records::grow_triangle): copying a record just written field by field stalls on its loads.
  void finish(Records& part, std::uint32_t call, const SetupVertex* const (&v)[3], bool back_facing) const;
  /// Adds the quad of four snapped corners (a segment's rectangle, in order around it, either winding) with
  /// the colour of `call`'s flat row from `v[0]`. False, adding nothing, when it is not a convex quad in the
  /// fast range: the caller draws it as two triangles. (One that misses the image is true, not added.)
  bool add_quad(std::uint32_t call, const SetupVertex (&v)[4]);
  /// Adds a 1-px line record (its box is computed here).
  void add_line(LineRecord line);
  /// Adds a point record to `part` (its box is computed here from its centre and radius; a point that can
  /// cover no sample of the image is not added). Reads only the setup's image and coverage: threads may fill
  /// different parts at once.
  void add_point(Records& part, PointRecord point) const;
  /// The pixels whose square, or with centre coverage whose centre, holds a point of the range [lo, hi]
  /// (1/256 px, x then y), clamped to the image: a triangle's box from its vertices, a point's from its disc.
  Rect pixel_box(const std::int64_t (&lo)[2], const std::int64_t (&hi)[2]) const;
  /// Records of every part.
  std::size_t record_count() const;
};

// Inline, with its helpers: geometry makes a record per triangle of a dense mesh, and a call into another
// file made the triangle's coordinates go through memory, stored as words and loaded as pairs (a stalled
// store-to-load forward per triangle).
namespace setup_detail {

// y down, interior on the side E > 0: a "left" edge runs upward (dy < 0); a "top" edge is horizontal and
// runs right (dy == 0, dx > 0), with the interior below it.
template <typename T>
inline bool is_top_left(const T& dx, const T& dy) {
  return dy < T(0) || (dy == T(0) && dx > T(0));
}

// Edges of a triangle with positive area; edge k runs between the other two vertices, so E_k is vertex
// k's weight times the area.
template <typename T>
inline EdgeFunctions<T> make_edges(const T (&x)[3], const T (&y)[3], const T& area) {
  EdgeFunctions<T> e;
  e.area = area;
  using Coefficient = typename EdgeFunctions<T>::Coefficient;
  for (int k = 0; k < 3; ++k) {
    const int from = (k + 1) % 3, to = (k + 2) % 3;
    const T a = y[from] - y[to], b = x[to] - x[from];
    e.a[k] = static_cast<Coefficient>(a), e.b[k] = static_cast<Coefficient>(b);
    const T bias = is_top_left(b, -a) ? T(0) : T(1);  // centres on an edge count for top/left only
    e.c[k] = -(a * x[from]) - b * y[from] - bias;
  }
  return e;
}

// True when a pixel centre of `box` is covered by `e` (the box holds at most kProbePixels pixels).
constexpr int kProbePixels = 16;
inline bool covers_a_centre(const EdgeFunctions<std::int64_t>& e, Rect box) {
  for (int y = box.y0; y < box.y1; ++y)
    for (int x = box.x0; x < box.x1; ++x) {
      const std::int64_t X = std::int64_t{x} * kSubpixelScale + kSubpixelScale / 2,
                         Y = std::int64_t{y} * kSubpixelScale + kSubpixelScale / 2;
      if (e.a[0] * X + e.b[0] * Y + e.c[0] >= 0 && e.a[1] * X + e.b[1] * Y + e.c[1] >= 0 &&
          e.a[2] * X + e.b[2] * Y + e.c[2] >= 0)
        return true;
    }
  return false;
}

// True when a sample of `pattern` (`count` positions) in a pixel of `box` is covered by `e` (the box holds at
// most kProbePixels pixels). A sample outside the vertices' range [lo, hi] (1/256 px) cannot be covered: most
// of a dense mesh's triangles hold no sample point even in their bounding box, and are told so by comparing
// coordinates alone.
inline bool covers_a_sample(const EdgeFunctions<std::int64_t>& e, Rect box, const std::int64_t (&lo)[2],
                            const std::int64_t (&hi)[2], const SamplePoint* pattern, int count) {
  for (int y = box.y0; y < box.y1; ++y)
    for (int x = box.x0; x < box.x1; ++x)
      for (int s = 0; s < count; ++s) {
        const std::int64_t X = std::int64_t{x} * kSubpixelScale + pattern[s].x,
                           Y = std::int64_t{y} * kSubpixelScale + pattern[s].y;
        if (X < lo[0] || X > hi[0] || Y < lo[1] || Y > hi[1]) continue;
        if (e.a[0] * X + e.b[0] * Y + e.c[0] >= 0 && e.a[1] * X + e.b[1] * Y + e.c[1] >= 0 &&
            e.a[2] * X + e.b[2] * Y + e.c[2] >= 0)
          return true;
      }
  return false;
}

}  // namespace setup_detail

[[gnu::always_inline]] inline Rect Setup::pixel_box(const std::int64_t (&lo)[2],
                                                    const std::int64_t (&hi)[2]) const {
  const std::int64_t size[2] = {width, height};
  int first[2], end[2];
  for (int d = 0; d < 2; ++d) {
    const std::int64_t f =
        centre_samples ? (lo[d] + kSubpixelScale / 2 - 1) >> kSubpixelBits : lo[d] >> kSubpixelBits;
    const std::int64_t l =
        centre_samples ? (hi[d] - kSubpixelScale / 2) >> kSubpixelBits : hi[d] >> kSubpixelBits;
    first[d] = static_cast<int>(std::clamp<std::int64_t>(f, 0, size[d]));
    end[d] = static_cast<int>(std::clamp<std::int64_t>(l + 1, 0, size[d]));
  }
  return {first[0], first[1], end[0], end[1]};
}

[[gnu::always_inline]] inline bool Setup::fast_record(const FastTriangle& t, TriangleRecord& r,
                                                      int (&order)[3]) const {
  std::int64_t x[3] = {t.x[0], t.x[1], t.x[2]}, y[3] = {t.y[0], t.y[1], t.y[2]};
  // The box in integers (the same pixels as pixel_span / centre_span give for these values): the pixels
  // whose square, or with centre coverage whose centre, holds a point of the vertices' range.
  const std::int64_t lo[2] = {std::min({x[0], x[1], x[2]}), std::min({y[0], y[1], y[2]})};
  const std::int64_t hi[2] = {std::max({x[0], x[1], x[2]}), std::max({y[0], y[1], y[2]})};
  r.box = pixel_box(lo, hi);
  if (r.box.empty()) return false;
  std::int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  if (area == 0) return false;  // degenerate: covers nothing
  order[0] = 0, order[1] = 1, order[2] = 2;
  if (area < 0) {  // both windings are drawn: normalize to positive area
    std::swap(x[1], x[2]), std::swap(y[1], y[2]), std::swap(order[1], order[2]);
    area = -area;
  }
  r.edges = setup_detail::make_edges(x, y, area);
  r.wide = TriangleRecord::kFast;
  // A small triangle that holds no pixel centre (or, multisampled, no sample) draws nothing: it gets no
  // record (most of a dense model's triangles are smaller than a pixel).
  if ((r.box.x1 - r.box.x0) * (r.box.y1 - r.box.y0) > setup_detail::kProbePixels) return true;
  if (centre_samples) return setup_detail::covers_a_centre(r.edges, r.box);
  return !pattern || setup_detail::covers_a_sample(r.edges, r.box, lo, hi, pattern, pattern_size);
}

/// Per tile, the records that may touch it, in scene order: for each part of the setup a flat array of
/// record references and, for tile t, the range [offsets[t], offsets[t + 1]) of it.
struct Bins {
  int tile = 64;              ///< tile side, pixels (a multiple of kBlock)
  int columns = 0, rows = 0;  ///< tiles across and down
  struct Part {
    std::vector<std::uint32_t> offsets;  ///< columns * rows + 1 entries
    PodArray<RecordRef> records;         ///< references into the setup part of the same index
  };
  std::vector<Part> parts;  ///< one per Setup::parts, in the same order
  Rect tile_rect(int index, int width, int height) const;
  /// Record-tile pairs of every part.
  std::size_t entry_count() const;
};

/// The bins' grid for `setup` and a tile side, with no part binned yet.
Bins bin_grid(const Setup& setup, int tile);
/// Bins every record of `part` by its bounding box, skipping tiles a triangle's edges exclude entirely.
/// Returns early, incomplete, once `meter` says the render must stop.
Bins::Part bin_part(const Bins& grid, const Setup& setup, const Records& part, StopMeter& meter);

}  // namespace raster::detail
