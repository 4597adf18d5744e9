#include "setup/setup.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace raster::detail {
namespace {

// Pixels whose square holds a point of [lo, hi] (1/256 px units), clipped to [0, size).
std::pair<int, int> pixel_span(double lo, double hi, int size) {
  const double first = std::floor(lo / kSubpixelScale), last = std::floor(hi / kSubpixelScale);
  return {static_cast<int>(std::clamp(first, 0.0, static_cast<double>(size))),
          static_cast<int>(std::clamp(last + 1, 0.0, static_cast<double>(size)))};
}

// Pixels whose centre lies in [lo, hi] (1/256 px units), clipped to [0, size): with centre coverage no other
// pixel can be covered, so the box is no larger than the samples it may hold (often empty for a sliver).
std::pair<int, int> centre_span(double lo, double hi, int size) {
  const double half = kSubpixelScale / 2;
  const double first = std::ceil((lo - half) / kSubpixelScale),
               last = std::floor((hi - half) / kSubpixelScale);
  return {static_cast<int>(std::clamp(first, 0.0, static_cast<double>(size))),
          static_cast<int>(std::clamp(last + 1, 0.0, static_cast<double>(size)))};
}

// False when the whole of `tile`'s sample points (any sample position) lies outside an edge of `e`.
template <int N>
bool may_touch(const EdgeFunctions<std::int64_t, N>& e, Rect tile) {
  const double x0 = double(tile.x0) * kSubpixelScale, x1 = double(tile.x1) * kSubpixelScale - 1;
  const double y0 = double(tile.y0) * kSubpixelScale, y1 = double(tile.y1) * kSubpixelScale - 1;
  for (int k = 0; k < N; ++k) {
    const double a = double(e.a[k]), b = double(e.b[k]);
    const double most = (a > 0 ? a * x1 : a * x0) + (b > 0 ? b * y1 : b * y0) + double(e.c[k]);  // exact
    if (most < 0) return false;
  }
  return true;
}

}  // namespace

std::uint32_t Setup::add_call(const DrawCall& call) {
  calls.push_back(call);
  calls.back().layout = VaryingLayout::of(call.mode.varyings);
  return static_cast<std::uint32_t>(calls.size() - 1);
}

void Setup::add_triangle(Records& part, std::uint32_t call, const SetupVertex (&given)[3],
                         bool back_facing) const {
  const SetupVertex* v[3] = {&given[0], &given[1], &given[2]};
  const double min_x = std::min({given[0].x, given[1].x, given[2].x}),
               max_x = std::max({given[0].x, given[1].x, given[2].x});
  const double min_y = std::min({given[0].y, given[1].y, given[2].y}),
               max_y = std::max({given[0].y, given[1].y, given[2].y});
  TriangleRecord r;
  constexpr double kFastUnits = kFastRangePx * kSubpixelScale;
  const bool wide = !(std::max(std::fabs(min_x), std::fabs(max_x)) <= kFastUnits &&
                      std::max(std::fabs(min_y), std::fabs(max_y)) <= kFastUnits);
  if (!wide) {
    FastTriangle t;
    for (int k = 0; k < 3; ++k)
      t.x[k] = static_cast<std::int64_t>(v[k]->x), t.y[k] = static_cast<std::int64_t>(v[k]->y);
    int order[3];
    if (!fast_record(t, r, order)) return;
    for (int k = 0; k < 3; ++k) v[k] = &given[order[k]];
  } else {
    const auto span = centre_samples ? centre_span : pixel_span;
    std::tie(r.box.x0, r.box.x1) = span(min_x, max_x, width);
    std::tie(r.box.y0, r.box.y1) = span(min_y, max_y, height);
    if (r.box.empty()) return;
    Wide x[3], y[3];
    for (int k = 0; k < 3; ++k) x[k] = Wide::from_double(v[k]->x), y[k] = Wide::from_double(v[k]->y);
    Wide area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if (area == Wide(0)) return;
    if (area.negative()) {
      std::swap(x[1], x[2]), std::swap(y[1], y[2]), std::swap(v[1], v[2]);
      area = -area;
    }
    r.wide = static_cast<std::uint32_t>(part.wide_edges.size());
    part.wide_edges.push_back(setup_detail::make_edges(x, y, area));
  }

  append(part, r, call, v, back_facing);
}

void Setup::append(Records& part, const TriangleRecord& r, std::uint32_t call,
                   const SetupVertex* const (&v)[3], bool back_facing) const {
  part.triangles.push_back(r);
  finish(part, call, v, back_facing);
}

void Setup::finish(Records& part, std::uint32_t call, const SetupVertex* const (&v)[3],
                   bool back_facing) const {
  TriangleRecord& r = part.triangles.back();
  // The flat rows from vertex 0, then each vertex's interpolated rows: one run of floats per vertex, since
  // a vertex holds its rows in the same order (VaryingLayout).
  const VaryingLayout& varyings = calls[call].layout;
  r.attributes = static_cast<std::uint32_t>(part.attributes.size());
  float* out = part.attributes.grow(static_cast<std::size_t>(varyings.record_floats()));
  for (int i = 0; i < kVaryingCount; ++i) {
    if (varyings.vertex_offset[i] < 0) continue;
    const Varying name = static_cast<Varying>(i);
    for (int k = 0; k < (varyings.how(name) == Interpolation::flat ? 1 : 3); ++k)
      std::copy_n(v[k]->values + varyings.vertex_offset[i], kVaryingWidth[i],
                  out + varyings.record_at(name, k));
  }
  r.call = call;
  r.back_facing = back_facing;
  part.order.push_back({static_cast<std::uint32_t>(part.triangles.size() - 1)});
}

std::size_t Setup::record_count() const {
  std::size_t n = 0;
  for (const Records& part : parts) n += part.order.size();
  return n;
}

bool Setup::add_quad(std::uint32_t call, const SetupVertex (&v)[4]) {
  const VaryingLayout& varyings = calls[call].layout;
  for (int i = 0; i < kVaryingCount; ++i)
    if (varyings.vertex_offset[i] >= 0 && varyings.how(static_cast<Varying>(i)) != Interpolation::flat)
      return false;  // a quad carries one flat row of each varying
  constexpr double kFastUnits = kFastRangePx * kSubpixelScale;
  std::int64_t x[4], y[4];
  for (int k = 0; k < 4; ++k) {
    if (!(std::fabs(v[k].x) <= kFastUnits && std::fabs(v[k].y) <= kFastUnits)) return false;
    x[k] = static_cast<std::int64_t>(v[k].x), y[k] = static_cast<std::int64_t>(v[k].y);
  }
  // Convex when every corner turns the same way; all straight is a line of no area, which draws nothing
  // (as its two triangles would not). Anything else, a corner snapped onto another or a twisted rectangle
  // far thinner than the grid, is left to the triangles.
  int left = 0, right = 0;
  std::int64_t area = 0;
  for (int k = 0; k < 4; ++k) {
    const int j = (k + 1) % 4, l = (k + 2) % 4;
    const std::int64_t turn = (x[j] - x[k]) * (y[l] - y[j]) - (y[j] - y[k]) * (x[l] - x[j]);
    left += turn > 0, right += turn < 0;
    area += x[k] * y[j] - x[j] * y[k];
  }
  if (!left && !right) return true;
  if (left != 4 && right != 4) return false;
  if (area < 0) {  // both windings are drawn: the other way round, the edges run as the triangles' do
    std::swap(x[1], x[3]), std::swap(y[1], y[3]);
    area = -area;
  }
  QuadRecord q;
  const std::int64_t lo[2] = {std::min({x[0], x[1], x[2], x[3]}), std::min({y[0], y[1], y[2], y[3]})};
  const std::int64_t hi[2] = {std::max({x[0], x[1], x[2], x[3]}), std::max({y[0], y[1], y[2], y[3]})};
  q.box = pixel_box(lo, hi);
  if (q.box.empty()) return true;
  q.edges.area = area;
  for (int k = 0; k < 4; ++k) {  // as make_edges makes a triangle's, from corner k to corner k + 1
    const int j = (k + 1) % 4;
    const std::int64_t a = y[k] - y[j], b = x[j] - x[k];
    q.edges.a[k] = static_cast<std::int32_t>(a), q.edges.b[k] = static_cast<std::int32_t>(b);
    q.edges.c[k] = -(a * x[k]) - b * y[k] - (setup_detail::is_top_left(b, -a) ? 0 : 1);
  }
  q.call = call;
  Records& part = last_part();
  q.attributes = static_cast<std::uint32_t>(part.attributes.size());
  float* out = part.attributes.grow(static_cast<std::size_t>(varyings.record_floats()));
  for (int i = 0; i < kVaryingCount; ++i)
    if (varyings.vertex_offset[i] >= 0)
      std::copy_n(v[0].values + varyings.vertex_offset[i], kVaryingWidth[i],
                  out + varyings.record_at(static_cast<Varying>(i), 0));
  part.order.push_back({RecordRef::kQuadBits | static_cast<std::uint32_t>(part.quads.size())});
  part.quads.push_back(q);
  return true;
}

void Setup::add_line(LineRecord line) {
  std::tie(line.box.x0, line.box.x1) = pixel_span(std::min(line.x0, line.x1) * kSubpixelScale,
                                                  std::max(line.x0, line.x1) * kSubpixelScale, width);
  std::tie(line.box.y0, line.box.y1) = pixel_span(std::min(line.y0, line.y1) * kSubpixelScale,
                                                  std::max(line.y0, line.y1) * kSubpixelScale, height);
  if (line.box.empty()) return;
  Records& part = last_part();
  part.order.push_back({RecordRef::kLineBit | static_cast<std::uint32_t>(part.lines.size())});
  part.lines.push_back(line);
}

void Setup::add_point(Records& part, PointRecord point) const {
  // The pixels whose square (or, with centre coverage, whose centre) holds a point of the disc's square.
  const std::int64_t lo[2] = {point.x - point.radius, point.y - point.radius};
  const std::int64_t hi[2] = {point.x + point.radius, point.y + point.radius};
  point.box = pixel_box(lo, hi);
  if (point.box.empty()) return;
  part.order.push_back({RecordRef::kPointBit | static_cast<std::uint32_t>(part.points.size())});
  part.points.push_back(point);
}

Rect Bins::tile_rect(int index, int width, int height) const {
  const int tx = index % columns, ty = index / columns;
  return {tx * tile, ty * tile, std::min(width, (tx + 1) * tile), std::min(height, (ty + 1) * tile)};
}

std::size_t Bins::entry_count() const {
  std::size_t n = 0;
  for (const Part& part : parts) n += part.records.size();
  return n;
}

Bins bin_grid(const Setup& setup, int tile) {
  Bins bins;
  bins.tile = tile;
  bins.columns = (setup.width + tile - 1) / tile;
  bins.rows = (setup.height + tile - 1) / tile;
  return bins;
}

Bins::Part bin_part(const Bins& grid, const Setup& setup, const Records& part, StopMeter& meter) {
  const int tile = grid.tile;
  const std::size_t tiles = static_cast<std::size_t>(grid.columns) * grid.rows;
  Bins::Part bins;
  std::vector<std::uint32_t> count(tiles + 1, 0);
  // Calls visit(tile index) for every tile record `ref` may touch.
  auto for_each_tile = [&](RecordRef ref, auto&& visit) {
    const std::uint32_t kind = ref.value & RecordRef::kKindBits;
    const std::uint32_t index = ref.value & ~RecordRef::kKindBits;
    const Rect box = kind == RecordRef::kQuadBits   ? part.quads[index].box
                     : kind == RecordRef::kLineBit  ? part.lines[index].box
                     : kind == RecordRef::kPointBit ? part.points[index].box
                                                    : part.triangles[index].box;
    const int tx0 = box.x0 / tile, tx1 = (box.x1 - 1) / tile, ty0 = box.y0 / tile, ty1 = (box.y1 - 1) / tile;
    if (tx0 == tx1 && ty0 == ty1) return visit(ty0 * grid.columns + tx0);  // one tile: no test
    const TriangleRecord* t = kind ? nullptr : &part.triangles[index];
    const QuadRecord* q = kind == RecordRef::kQuadBits ? &part.quads[index] : nullptr;
    const bool test = t && t->wide == TriangleRecord::kFast;
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) {
        const int at = ty * grid.columns + tx;
        const Rect rect = grid.tile_rect(at, setup.width, setup.height);
        if ((test && !may_touch(t->edges, rect)) || (q && !may_touch(q->edges, rect))) continue;
        visit(at);
      }
  };
  // Both passes look at the deadline: millions of records take tens of milliseconds.
  for (const RecordRef ref : part.order) {
    if (meter.add(StopMeter::kPrimitiveWork)) return bins;  // the caller sees meter.stopped()
    for_each_tile(ref, [&](int at) { ++count[at + 1]; });
  }
  for (std::size_t t = 0; t < tiles; ++t) count[t + 1] += count[t];
  // Counted, not yet allocated: a few huge triangles over many tiles can need more than their records.
  if (!meter.stop().reserve(cost::kRenderPerBinEntry * static_cast<std::int64_t>(count[tiles]))) return bins;
  bins.offsets = count;
  bins.records.resize_uninitialized(count[tiles]);
  for (const RecordRef ref : part.order) {
    if (meter.add(StopMeter::kPrimitiveWork)) return bins;
    for_each_tile(ref, [&](int at) { bins.records[count[at]++] = ref; });
  }
  return bins;
}

}  // namespace raster::detail
