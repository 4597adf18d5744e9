// Render: runs geometry once, then the raster stage over horizontal bands. Each band owns its rows and
// applies every op in scene order, so the image is the same bytes for any number of bands.
#include "raster/render.h"

#include <algorithm>
#include <thread>
#include <vector>

#include "framebuffer.h"
#include "geometry.h"
#include "raster.h"

namespace raster {

Image render(const Scene& scene, const RenderPlan& plan, const RenderControl& control) {
  std::atomic<bool> stopped{false};  // set by whichever band first sees the deadline or the cancel flag
  const detail::Stop stop{control.deadline, control.cancel, &stopped, &control.clock};
  const auto cancelled = [] { return RenderCancelled("render stopped: deadline passed or cancelled"); };
  detail::StopMeter meter(stop);  // the calling thread's, for geometry and allocation
  const detail::DrawList list = detail::build_draw_list(scene, plan, meter);
  if (meter.stopped()) throw cancelled();

  // Buffers are cleared as they are allocated, looking at the deadline every megabyte.
  Image image = detail::make_color_buffer(plan, scene.background, meter);
  // Anti-aliasing: one colour plane (and depth plane) per sample position, drawn like an aliased image
  // whose coverage is tested at that position, then resolved into `image`. Aliased: `image` itself.
  const std::vector<detail::SamplePoint>& pattern = detail::sample_pattern(plan.samples);
  std::vector<Image> planes;
  std::vector<std::vector<float>> depth;
  for (std::size_t s = 0; s < pattern.size(); ++s) {
    if (plan.samples > 1) planes.push_back(detail::make_color_buffer(plan, scene.background, meter, false));
    depth.push_back(detail::make_depth_buffer(plan, meter));
  }
  if (meter.stopped()) throw cancelled();

  if (control.stats) {  // what was actually allocated for pixels, for checking against the plan
    std::int64_t bytes = static_cast<std::int64_t>(image.pixels.size());
    for (const Image& p : planes) bytes += static_cast<std::int64_t>(p.pixels.size());
    for (const auto& d : depth) bytes += static_cast<std::int64_t>(d.size() * sizeof(float));
    control.stats->pixel_bytes = bytes;
  }
  auto draw_band = [&](detail::Rect rows) {
    detail::StopMeter band_meter(stop);  // each band counts its own work
    if (band_meter.check()) return;      // a deadline already past stops even the smallest render
    for (std::size_t s = 0; s < pattern.size(); ++s) {
      Image& target = planes.empty() ? image : planes[s];
      detail::draw(list, target, depth[s].empty() ? nullptr : depth[s].data(), rows, band_meter, pattern[s]);
      if (band_meter.stopped()) return;
    }
    if (planes.empty()) return;
    // The resolve reads every sample plane: up to the whole pixel-storage limit, so it is metered too.
    const int rows_per_check = std::max(
        1, static_cast<int>(detail::StopMeter::kWorkPerCheck / (std::int64_t{image.width} * plan.samples)));
    for (int y = rows.y0; y < rows.y1; y += rows_per_check) {
      if (y > rows.y0 && band_meter.check()) return;
      detail::resolve(planes, image, {rows.x0, y, rows.x1, std::min(rows.y1, y + rows_per_check)});
    }
  };
  const int bands = plan.threads;
  if (bands <= 1) {
    draw_band(detail::band(plan, 0, 1));  // small work: no hand-off at all
  } else {
    std::vector<std::jthread> workers;
    workers.reserve(bands - 1);
    for (int b = 1; b < bands; ++b) workers.emplace_back([&, b] { draw_band(detail::band(plan, b, bands)); });
    draw_band(detail::band(plan, 0, bands));
  }  // jthreads join here
  if (stopped) throw cancelled();
  return image;
}

bool detail::Stop::now() const {
  if (stopped->load(std::memory_order_relaxed)) return true;
  const bool stop = (cancel && cancel->load(std::memory_order_relaxed)) ||
                    (clock && *clock ? (*clock)() : std::chrono::steady_clock::now()) >= deadline;
  if (stop) stopped->store(true, std::memory_order_relaxed);
  return stop;
}

Image render(const Scene& scene, const Limits& limits) {
  return render(scene, plan(scene, limits));
}

}  // namespace raster
