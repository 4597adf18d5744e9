// Render: runs geometry once, then the raster stage over horizontal bands. Each band owns its rows and
// applies every op in scene order, so the image is the same bytes for any number of bands.
#include "raster/render.h"

#include <thread>
#include <vector>

#include "framebuffer.h"
#include "geometry.h"
#include "raster.h"

namespace raster {

Image render(const Scene& scene, const RenderPlan& plan, const RenderControl& control) {
  const detail::DrawList list = detail::build_draw_list(scene, plan);
  std::atomic<bool> stopped{false};  // set by whichever band first sees the deadline or the cancel flag
  const detail::Stop stop{control.deadline, control.cancel, &stopped};
  Image image = detail::make_color_buffer(plan, scene.background);
  std::vector<float> depth = detail::make_depth_buffer(plan);  // empty unless the plan has 3D content
  float* const z = depth.empty() ? nullptr : depth.data();
  const int bands = plan.threads;
  if (bands <= 1) {
    detail::draw(list, image, z, detail::band(plan, 0, 1), stop);  // small work: no hand-off at all
    if (stopped) throw RenderCancelled("render stopped: deadline passed or cancelled");
    return image;
  }
  {
    std::vector<std::jthread> workers;
    workers.reserve(bands - 1);
    for (int b = 1; b < bands; ++b)
      workers.emplace_back([&, b] { detail::draw(list, image, z, detail::band(plan, b, bands), stop); });
    detail::draw(list, image, z, detail::band(plan, 0, bands), stop);
  }  // jthreads join here
  if (stopped) throw RenderCancelled("render stopped: deadline passed or cancelled");
  return image;
}

Image render(const Scene& scene, const Limits& limits) { return render(scene, plan(scene, limits)); }

}  // namespace raster
