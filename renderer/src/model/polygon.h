// Faces of more than three corners split into triangles, one way for every format that stores polygons
// (OBJ, PLY), so that a model reads alike in each: a quad on its shorter diagonal (tinyobjloader's rule,
// kept from when OBJ faces were split by it), a larger polygon by ear clipping in its own plane.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "base/budget_ask.h"
#include "raster/scene.h"

namespace raster {

/// Splits the faces of one model. Keeps its buffers from face to face (a model of many pentagons would
/// otherwise allocate seven arrays for each) and counts ear clipping's work against a budget: a polygon of
/// n corners with r reflex ones costs about n x (r + 1) point tests and up to n steps around it per triangle,
/// so one face of a million concave corners would take hours. 2^28 units take about a second.
class PolygonSplitter {
 public:
  PolygonSplitter() = default;
  /// With a meter, the work is also counted there: a face that takes long to split is deadline-checked.
  explicit PolygonSplitter(detail::ReadMeter* meter) : meter_(meter) {}
  /// Appends the triangles of the polygon whose corners, in order (counter-clockwise seen from the front),
  /// are at `corners`: n - 2 triangles as triples of indices into `corners`, wound as the polygon is. A
  /// simple polygon, convex or not, is covered exactly; a self-intersecting or degenerate one still gets
  /// n - 2 triangles. Throws SceneError(limit) when the model's budget runs out.
  void split(std::span<const Vec3> corners, std::vector<std::array<std::uint32_t, 3>>& out);

 private:
  struct P2 {
    double x = 0, y = 0;
  };
  void project(std::span<const Vec3> corners);
  void ear_clip(std::span<const Vec3> corners, std::vector<std::array<std::uint32_t, 3>>& out);
  void charge(std::int64_t work, std::size_t n);

  std::int64_t work_left_ = std::int64_t{1} << 28;  ///< point tests and steps still allowed
  detail::ReadMeter* meter_ = nullptr;              ///< the reader's deadline meter, if any
  // The polygon being clipped: its corners in its plane, the ring that remains, reflex corners.
  std::vector<P2> p_;
  std::vector<std::uint32_t> prev_, next_, reflexes_;
  std::vector<char> reflex_, removed_, ear_;
};

}  // namespace raster
