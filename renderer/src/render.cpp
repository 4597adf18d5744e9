// Render: Scene + RenderPlan -> Image. Geometry and setup run once, the records are binned to tiles once,
// and threads take tiles: each tile draws its bin in scene order into pixels no other tile owns, so the
// image is the same bytes for any number of threads and any tile size.
#include "raster/render.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <type_traits>
#include <vector>

#include "base/parallel.h"
#include "coverage/coverage.h"
#include "coverage/line.h"
#include "coverage/point.h"
#include "framebuffer/framebuffer.h"
#include "framebuffer/tiles.h"
#include "geometry/geometry.h"
#include "setup/setup.h"
#include "shade/edges.h"
#include "shade/program.h"
#include "shade/shade.h"
#include "shader/ir.h"

namespace raster {
namespace {

using detail::Rect;

/// What every tile reads (shared, immutable while tiles draw) and writes (each tile its own pixels).
struct Frame {
  const detail::Setup& setup;
  const detail::Bins& bins;
  const RenderPlan& plan;
  Image& image;
  const detail::Programs& programs;
};

/// A thread's own state while it draws tiles: its programs' registers, and where a program of its stopped
/// the render (its loops past their bound).
struct TileThread {
  detail::ProgramThread programs;
  detail::ProgramFault fault;
};

// The coverage routine the plan's anti-aliasing asks for.
template <typename T, int N, typename Shader>
void cover(const detail::EdgeFunctions<T, N>& e, Rect clip, Coverage coverage, const detail::Surface& surface,
           detail::Lanes lanes, detail::StopMeter& meter, Shader& shader) {
  switch (coverage) {
    case Coverage::centre:
    case Coverage::edge_samples:  // never a surface's mode: its passes are centre, then samples
      return detail::cover(e, clip, detail::SamplePoint{}, lanes, meter, shader);
    case Coverage::samples:
      return detail::cover_samples(e, clip, surface.pattern, surface.sample_count, lanes, meter, shader);
    case Coverage::area:
      return detail::cover_area(e, clip, lanes, meter, shader);
  }
}

// Edge sampling's second pass, for records that write pixels directly (lines, points): draw(part) for each
// part of `clip` in a block holding an edge pixel (the blocks' other pixels are scratch, never copied back).
template <class Draw>
void each_edge_block(Rect clip, const detail::EdgePixels& edges, Draw&& draw) {
  for (int y0 = clip.y0 / detail::kBlock * detail::kBlock; y0 < clip.y1; y0 += detail::kBlock)
    for (int x0 = clip.x0 / detail::kBlock * detail::kBlock; x0 < clip.x1; x0 += detail::kBlock)
      if (edges.view().at(x0, y0))
        draw(Rect{std::max(clip.x0, x0), std::max(clip.y0, y0), std::min(clip.x1, x0 + detail::kBlock),
                  std::min(clip.y1, y0 + detail::kBlock)});
}

// Covers `clip` with `e` into `shader`: as the surface's mode says, or, with `edges` (edge sampling's second
// pass), multisampled at the edge pixels only.
template <typename T, int N, typename Shader>
[[gnu::always_inline]] inline void cover_or_edges(const detail::EdgeFunctions<T, N>& e, Rect clip,
                                                  Coverage coverage, const detail::Surface& surface,
                                                  const detail::EdgePixels* edges, detail::Lanes lanes,
                                                  detail::StopMeter& meter, Shader& shader) {
  if (!edges) return cover(e, clip, coverage, surface, lanes, meter, shader);
  const detail::BlockMasks pixels = edges->view();
  detail::OnlyPixels<Shader> only{shader, pixels, surface.sample_count};
  detail::cover_samples(e, clip, surface.pattern, surface.sample_count, lanes, meter, only, &pixels);
}

// Inlined into the tile loop, where `clip` lives in registers: as a call, the Rect arrived in two registers,
// was stored as two words and loaded as one 16-byte vector, a stalled store-to-load forward per record.
template <int C>
[[gnu::always_inline]] inline void draw_triangle(const detail::Setup& setup, const detail::Records& part,
                                                 const detail::TriangleRecord& t,
                                                 const detail::Surface& surface, Rect clip, Coverage coverage,
                                                 const detail::EdgePixels* edges, detail::Lanes lanes,
                                                 detail::StopMeter& meter) {
  const float* attributes = part.attributes.data() + t.attributes;
  if (t.wide != detail::TriangleRecord::kFast) {
    const detail::EdgeFunctions<detail::Wide>& e = part.wide_edges[t.wide];
    const detail::Wide scale(detail::kSubpixelScale);
    const double dx[3] = {(e.a[0] * scale).to_double(), (e.a[1] * scale).to_double(),
                          (e.a[2] * scale).to_double()};
    const double dy[3] = {(e.b[0] * scale).to_double(), (e.b[1] * scale).to_double(),
                          (e.b[2] * scale).to_double()};
    detail::TriangleShader<C> shader(setup.calls[t.call], t.back_facing, attributes, surface, dx, dy,
                                     e.area.to_double());
    cover_or_edges(e, clip, coverage, surface, edges, lanes, meter, shader);
  } else {
    const detail::EdgeFunctions<std::int64_t>& e = t.edges;
    const double dx[3] = {double(e.a[0] * detail::kSubpixelScale), double(e.a[1] * detail::kSubpixelScale),
                          double(e.a[2] * detail::kSubpixelScale)};
    const double dy[3] = {double(e.b[0] * detail::kSubpixelScale), double(e.b[1] * detail::kSubpixelScale),
                          double(e.b[2] * detail::kSubpixelScale)};
    detail::TriangleShader<C> shader(setup.calls[t.call], t.back_facing, attributes, surface, dx, dy,
                                     double(e.area));
    cover_or_edges(e, clip, coverage, surface, edges, lanes, meter, shader);
  }
}

// GCC drops __builtin_prefetch here (it sees a call without effects); an asm statement stays.
template <typename T>
inline void fetch(const T* p) {
#if defined(__x86_64__)
  asm volatile("prefetcht0 %0" : : "m"(*reinterpret_cast<const char*>(p)));
#else
  __builtin_prefetch(p);
#endif
}

// A bin lists records from all over the setup (scene order, not memory order): without help every record
// is a cache miss. Records kAhead entries on are fetched, and the attributes of those half as far on (whose
// record has arrived by then).
inline void prefetch(const detail::Records& part, const detail::Bins::Part& bins, std::uint32_t i,
                     std::uint32_t end) {
  constexpr std::uint32_t kAhead = 8;
  if (i + kAhead < end) {
    const std::uint32_t ref = bins.records[i + kAhead].value;
    if (!(ref & detail::RecordRef::kKindBits)) fetch(&part.triangles[ref]);
  }
  if (i + kAhead / 2 < end) {
    const std::uint32_t ref = bins.records[i + kAhead / 2].value;
    if (ref & detail::RecordRef::kKindBits) return;
    const detail::TriangleRecord& t = part.triangles[ref];
    fetch(reinterpret_cast<const char*>(&t) + 64);  // the record's second cache line
    fetch(&part.attributes[t.attributes]);
  }
}

// Draws tile `tile`'s bin into `surface`: every pixel, or (`edges` not null: edge sampling's second pass)
// the edge pixels only.
// A shader primitive's record: its program run over `clip`. False when the render must stop; a pixel past
// its loop bound stops every thread, as a deadline does.
bool draw_program_record(const Frame& f, int program, const detail::Surface& surface, Rect clip,
                         const detail::EdgePixels* edges, TileThread& thread, detail::StopMeter& meter) {
  const detail::BlockMasks edge_masks = edges ? edges->view() : detail::BlockMasks{};
  if (detail::draw_program(f.programs, program, thread.programs, surface, clip, edges ? &edge_masks : nullptr,
                           meter, thread.fault))
    return true;
  if (thread.fault.shader >= 0) meter.stop().stopped->store(true), meter.check();
  return false;
}

template <int C>
void draw_bin(const Frame& f, int tile, const detail::Surface& surface, const detail::EdgePixels* edges,
              TileThread& thread, detail::StopMeter& meter) {
  const Rect rect = f.bins.tile_rect(tile, f.plan.width, f.plan.height);
  const detail::Lanes lanes = f.plan.scalar_coverage      ? detail::Lanes::scalar
                              : f.plan.simd == Simd::avx2 ? detail::Lanes::avx2
                                                          : detail::Lanes::sse2;
  const Coverage coverage = surface.coverage_mode;
  // A union-coverage primitive (its own draw call) accumulates over its consecutive records, and is
  // composited over the pixels they reached when the next record belongs to another call.
  constexpr std::uint32_t kNone = ~0u;
  std::uint32_t open = kNone;
  Rect reached;
  auto close = [&] {
    if (open != kNone) detail::composite_union<C>(surface, reached);
    open = kNone;
  };
  for (std::size_t p = 0; p < f.bins.parts.size(); ++p) {  // parts in scene order, as one sequence
    const detail::Records& part = f.setup.parts[p];
    const detail::Bins::Part& bins = f.bins.parts[p];
    const std::uint32_t end = bins.offsets[tile + 1];
    for (std::uint32_t i = bins.offsets[tile]; i < end; ++i) {
      if (meter.add(detail::StopMeter::kPrimitiveWork)) return;
      prefetch(part, bins, i, end);
      const std::uint32_t ref = bins.records[i].value;
      // A union primitive stays open over its consecutive triangles and quads (`clip`, the pixels they
      // reach): opened by the first, composited when another call's record comes.
      auto join = [&](std::uint32_t call, Rect clip) {
        if (call != open) {
          close();
          if (coverage == Coverage::area && f.setup.calls[call].mode.union_coverage)
            open = call, reached = clip;
        } else {
          reached = {std::min(reached.x0, clip.x0), std::min(reached.y0, clip.y0),
                     std::max(reached.x1, clip.x1), std::max(reached.y1, clip.y1)};
        }
      };
      if ((ref & detail::RecordRef::kKindBits) == detail::RecordRef::kQuadBits) {
        const detail::QuadRecord& q = part.quads[ref & ~detail::RecordRef::kKindBits];
        const Rect clip{std::max(rect.x0, q.box.x0), std::max(rect.y0, q.box.y0), std::min(rect.x1, q.box.x1),
                        std::min(rect.y1, q.box.y1)};
        if (edges && !edges->any_in(clip)) continue;
        if (const std::int32_t program = f.setup.calls[q.call].shader; program >= 0) {  // a shader's pixels
          if (close(), draw_program_record(f, program, surface, clip, edges, thread, meter)) continue;
          return;
        }
        join(q.call, clip);
        // Flat: the shader reads the colour row only, never the barycentric steps.
        const double none[3] = {0, 0, 0};
        detail::TriangleShader<C> shader(f.setup.calls[q.call], false, part.attributes.data() + q.attributes,
                                         surface, none, none, 1.0);
        cover_or_edges(q.edges, clip, coverage, surface, edges, lanes, meter, shader);
        continue;
      }
      if (ref & detail::RecordRef::kLineBit) {
        close();
        const detail::LineRecord& line = part.lines[ref & ~detail::RecordRef::kKindBits];
        const auto draw = [&](Rect part) {
          detail::draw_line(line, f.setup.calls[line.call].mode, surface, part, meter);
        };
        edges ? each_edge_block(rect, *edges, draw) : draw(rect);
        continue;
      }
      if (ref & detail::RecordRef::kPointBit) {
        close();
        const detail::PointRecord& point = part.points[ref & ~detail::RecordRef::kKindBits];
        const auto draw = [&](Rect part) {
          detail::draw_point(point, f.setup.calls[point.call].mode, surface, part, meter);
        };
        edges ? each_edge_block(rect, *edges, draw) : draw(rect);
        continue;
      }
      const detail::TriangleRecord& t = part.triangles[ref];
      const Rect clip{std::max(rect.x0, t.box.x0), std::max(rect.y0, t.box.y0), std::min(rect.x1, t.box.x1),
                      std::min(rect.y1, t.box.y1)};
      if (edges && !edges->any_in(clip)) continue;
      join(t.call, clip);
      draw_triangle<C>(f.setup, part, t, surface, clip, coverage, edges, lanes, meter);
    }
  }
  close();
}

// Draws one tile: straight into the image when the plan says so; else its bin into the thread's tile storage
// (framebuffer/tiles.h), resolved when multisampled, copied back.
template <int C>
void draw_tile(const Frame& f, int tile, detail::TileStorage& storage, TileThread& thread,
               detail::StopMeter& meter) {
  if (f.plan.tiles_in_place)
    return draw_bin<C>(f, tile, detail::image_surface<C>(f.image, f.plan, storage), nullptr, thread, meter);
  const Rect rect = f.bins.tile_rect(tile, f.plan.width, f.plan.height);
  const detail::SamplePoint* pattern =
      f.plan.coverage == Coverage::samples ? detail::sample_pattern(f.plan.samples).data() : nullptr;
  detail::Surface surface = detail::open_tile<C>(storage, f.plan, pattern, rect, f.image);
  if (pattern) surface.centroids = detail::centroid_offsets(f.plan.samples);
  draw_bin<C>(f, tile, surface, nullptr, thread, meter);
  if (meter.stopped()) return;
  if (f.plan.coverage == Coverage::samples) {
    detail::resolve_samples<C>(surface, rect);
    meter.add(std::int64_t{rect.x1 - rect.x0} * (rect.y1 - rect.y0));
  }
  detail::close_tile<C>(surface, rect, f.image);
}

// Edge sampling's second pass over one tile: its edge pixels (none: nothing to do) drawn again from the
// background, multisampled, resolved and copied over the aliased pixels there.
template <int C>
void draw_edge_tile(const Frame& f, int tile, const detail::EdgePixels& edges, const std::uint8_t* background,
                    detail::TileStorage& storage, TileThread& thread, detail::StopMeter& meter) {
  const Rect rect = f.bins.tile_rect(tile, f.plan.width, f.plan.height);
  if (!edges.any_in(rect)) return;
  const detail::SamplePoint* pattern = detail::sample_pattern(f.plan.samples).data();
  detail::Surface surface =
      detail::open_edge_tile<C>(storage, f.plan, pattern, rect, edges.view(), background);
  surface.centroids = detail::centroid_offsets(f.plan.samples);
  draw_bin<C>(f, tile, surface, &edges, thread, meter);
  if (meter.stopped()) return;
  detail::resolve_samples<C>(surface, rect);
  detail::close_edge_tile<C>(surface, rect, edges.view(), f.image);
}

// `draw` for the image's channel count (a constant of the kernels).
template <class Draw>
void with_channels(int channels, Draw&& draw) {
  switch (channels) {
    case 1:
      return draw(std::integral_constant<int, 1>{});
    case 2:
      return draw(std::integral_constant<int, 2>{});
    case 3:
      return draw(std::integral_constant<int, 3>{});
    default:
      return draw(std::integral_constant<int, 4>{});
  }
}

// The setup's records binned to the plan's tiles: each part on its own (on every render thread for a large
// mesh's parts). Incomplete once `stop` says the render must stop.
detail::Bins bin_records(const detail::Setup& setup, const RenderPlan& plan, const detail::Stop& stop) {
  detail::Bins bins = detail::bin_grid(setup, plan.tile);
  bins.parts.resize(setup.parts.size());
  detail::parallel_for(setup.parts.size() > 1 ? plan.threads : 1, setup.parts.size(), stop,
                       [&](std::size_t p, detail::StopMeter& own, int) {
                         bins.parts[p] = detail::bin_part(bins, setup, setup.parts[p], own);
                       });
  return bins;
}

// What was actually allocated, for checking against the plan: pixel storage (the image and every thread's
// tile storage), the bins, and the records and bin entries they hold.
void count_storage(const detail::Setup& setup, const detail::Bins& bins, const Image& image,
                   const std::vector<detail::TileStorage>& storage, RenderStats& stats) {
  std::int64_t bytes = static_cast<std::int64_t>(image.pixels.size());
  for (const detail::TileStorage& t : storage) bytes += t.bytes();
  stats.pixel_bytes = bytes;
  std::size_t bin_bytes = 0;
  for (const detail::Bins::Part& part : bins.parts)
    bin_bytes +=
        part.records.size() * sizeof(detail::RecordRef) + part.offsets.size() * sizeof(std::uint32_t);
  stats.bin_bytes = static_cast<std::int64_t>(bin_bytes);
  stats.records = static_cast<std::int64_t>(setup.record_count());
  stats.bin_entries = static_cast<std::int64_t>(bins.entry_count());
}

// A program that went past its loop bound on some thread: the error that names the loop and the pixel (the
// first pixel a thread found; with one thread, the first in tile order).
void check_programs(const std::vector<TileThread>& threads, const RenderPlan& plan) {
  for (const TileThread& t : threads) {
    if (t.fault.shader < 0) continue;
    const ShaderPlan& p = plan.shaders[static_cast<std::size_t>(t.fault.shader)];
    const shader::SourcePos at = p.shader->program().loops[t.fault.loop].pos;
    const std::string limit = std::to_string(p.max_iterations);
    throw SceneError(ErrorKind::program,
                     "the program's loop at line " + std::to_string(at.line) + " ran past " + limit +
                         " iterations at pixel (" + std::to_string(t.fault.x) + ", " +
                         std::to_string(t.fault.y) + "): a pixel may take " + limit +
                         " iterations of all its loops together",
                     {"/primitives/" + std::to_string(p.primitive) + "/source", 0,
                      static_cast<std::size_t>(at.line), static_cast<std::size_t>(at.column)});
  }
}

// Edge sampling's second pass: the edge pixels of the aliased picture found, then drawn again multisampled.
void draw_edges(const Frame& frame, const detail::Stop& stop, int threads,
                std::vector<detail::TileStorage>& scratch, std::vector<TileThread>& tile_threads,
                const std::vector<std::uint8_t>& background, const RenderControl& control,
                detail::StopMeter& meter) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  const detail::EdgePixels edges = detail::find_edge_pixels(frame.image, meter);
  if (meter.stopped()) return;
  const Clock::time_point found = Clock::now();
  if (control.stats) {
    control.stats->edge_blocks = edges.blocks, control.stats->edge_pixels = edges.pixels;
    control.stats->pixel_bytes += edges.bytes;
    control.stats->find_edges_ms = std::chrono::duration<double, std::milli>(found - start).count();
  }
  const int tiles = frame.bins.columns * frame.bins.rows;
  detail::parallel_for(threads, static_cast<std::size_t>(tiles), stop,
                       [&](std::size_t t, detail::StopMeter& own, int thread) {
                         with_channels(frame.image.channels(), [&](auto c) {
                           draw_edge_tile<c.value>(frame, static_cast<int>(t), edges, background.data(),
                                                   scratch[static_cast<std::size_t>(thread)],
                                                   tile_threads[static_cast<std::size_t>(thread)], own);
                         });
                       });
  if (control.stats)
    control.stats->edge_tiles_ms = std::chrono::duration<double, std::milli>(Clock::now() - found).count();
}

}  // namespace

Image render(const Scene& scene, const RenderPlan& plan, const RenderControl& control) {
  std::atomic<bool> stopped{false};      // set by whichever thread first sees the deadline or the cancel flag
  std::atomic<std::int64_t> refused{0};  // bytes the budget refused (a refusal stops the render too)
  const detail::Stop stop{control.deadline, control.cancel, &stopped,
                          &control.clock,   control.budget, &refused};
  const auto cancelled = [&] {  // why the render stopped: the budget refused memory, or time ran out
    if (refused.load()) throw MemoryRefused(refused.load(), "the render's records and tile bins");
    throw RenderCancelled("render stopped: deadline passed or cancelled");
  };
  detail::StopMeter meter(stop);  // the calling thread's, for geometry, binning and allocation
  using Clock = std::chrono::steady_clock;
  auto lap = [&, last = Clock::now()](double RenderStats::*field) mutable {
    const Clock::time_point now = Clock::now();
    if (control.stats) control.stats->*field = std::chrono::duration<double, std::milli>(now - last).count();
    last = now;
  };
  const detail::Setup setup = detail::build_setup(scene, plan, meter);
  if (meter.stopped()) cancelled();
  const detail::Programs programs = detail::prepare_programs(scene, plan, meter);
  if (meter.stopped()) cancelled();
  lap(&RenderStats::geometry_ms);
  const detail::Bins bins = bin_records(setup, plan, stop);
  if (stopped) cancelled();
  lap(&RenderStats::bin_ms);

  // Buffers are cleared as they are allocated, looking at the deadline every megabyte.
  Image image = detail::make_color_buffer(plan, scene.background, meter);
  if (meter.stopped()) cancelled();

  const int tiles = bins.columns * bins.rows;
  const int threads = std::min(plan.threads, tiles);
  // Each thread's tile storage, as the plan sized it; allocated here so the stats below can count it.
  std::vector<detail::TileStorage> scratch;
  scratch.reserve(static_cast<std::size_t>(std::max(threads, 1)));
  for (int t = 0; t < std::max(threads, 1); ++t) scratch.emplace_back(plan.tile_storage);
  std::vector<TileThread> tile_threads(static_cast<std::size_t>(std::max(threads, 1)));
  if (control.stats) count_storage(setup, bins, image, scratch, *control.stats);
  lap(&RenderStats::clear_ms);
  const Frame frame{setup, bins, plan, image, programs};
  // The background as a pixel of the image's format, before anything is drawn (edge sampling redraws its
  // blocks from it).
  const std::vector<std::uint8_t> background(image.pixels.begin(), image.pixels.begin() + image.channels());
  // Tiles are taken column by column; which thread takes one does not change its bytes. Threads drawing at
  // once are then above and below each other: side by side, drawing in place, they would share the cache
  // line at their common edge in every row (the image is only 16-byte aligned). One thread: no hand-off.
  detail::parallel_for(threads, static_cast<std::size_t>(tiles), stop,
                       [&](std::size_t piece, detail::StopMeter& own, int thread) {
                         const int t =
                             static_cast<int>(piece % static_cast<std::size_t>(bins.rows)) * bins.columns +
                             static_cast<int>(piece / static_cast<std::size_t>(bins.rows));
                         with_channels(image.channels(), [&](auto c) {
                           draw_tile<c.value>(frame, t, scratch[static_cast<std::size_t>(thread)],
                                              tile_threads[static_cast<std::size_t>(thread)], own);
                         });
                       });
  check_programs(tile_threads, plan);
  if (stopped) cancelled();
  lap(&RenderStats::tiles_ms);
  if (plan.coverage == Coverage::edge_samples) {
    // The aliased picture is whole: the blocks where it shows an edge, then those drawn again multisampled.
    draw_edges(frame, stop, threads, scratch, tile_threads, background, control, meter);
    check_programs(tile_threads, plan);
    if (stopped) cancelled();
  }
  if (control.stats) {
    control.stats->shaded_pixels = 0;
    for (const detail::TileStorage& t : scratch) control.stats->shaded_pixels += t.shaded;
    for (const TileThread& t : tile_threads) control.stats->pixel_bytes += t.programs.bytes();
    control.stats->pixel_bytes += programs.bytes();
  }
  return image;
}

Image render(const Scene& scene, const Limits& limits) {
  return render(scene, plan(scene, limits));
}

}  // namespace raster
