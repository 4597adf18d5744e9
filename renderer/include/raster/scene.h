// Scene: the plain data a render is made from, and its parser (JSON text -> Scene, with precise errors).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "raster/error.h"

namespace raster {

/// 8-bit straight (not premultiplied) colour; 0 = none, 255 = full. Alpha 255 is opaque.
/// Scene colours are quantized to 8 bits when parsed, so equality tests on them are exact.
struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  friend bool operator==(const Rgba8&, const Rgba8&) = default;
  bool is_grey() const { return r == g && g == b; }
  bool is_opaque() const { return a == 255; }
};

/// A point in image space: pixels, origin at the top-left corner of the image, x right, y down.
/// Pixel (i, j) is the square [i, i+1) x [j, j+1); its centre is (i + 0.5, j + 0.5).
struct Point2 {
  double x = 0, y = 0;
};

enum class PrimitiveKind : std::uint8_t { triangle, line, polyline };

/// One drawable. Vertices and colours live in the Scene's flat arrays; a primitive names ranges of them,
/// so a scene of a million triangles is three vectors, not a million small ones.
struct Primitive {
  PrimitiveKind kind = PrimitiveKind::triangle;
  std::uint32_t first_point = 0;  ///< index into Scene::points of the first vertex
  std::uint32_t point_count = 0;  ///< triangle: 3; line: 2; polyline: >= 2
  std::uint32_t first_color = 0;  ///< index into Scene::colors
  bool per_vertex_color = false;  ///< true: point_count colours from first_color; false: one flat colour
  bool fill = true;               ///< triangles: false draws the outline with the line rule
  bool closed = false;            ///< polylines: also join the last point to the first
};

/// The image dimensions, their background and the primitives drawn over it in array order.
struct Scene {
  int width = 0;               ///< pixels, >= 1
  int height = 0;              ///< pixels, >= 1
  Rgba8 background{0, 0, 0, 255};
  std::vector<Primitive> primitives;  ///< drawn in this order; later ones are on top
  std::vector<Point2> points;         ///< all vertices, referenced by Primitive::first_point
  std::vector<Rgba8> colors;          ///< all colours, referenced by Primitive::first_color

  /// Colour of vertex `k` (0-based within the primitive) of `p`, flat or per-vertex.
  Rgba8 vertex_color(const Primitive& p, std::uint32_t k) const {
    return colors[p.first_color + (p.per_vertex_color ? k : 0)];
  }
};

/// What the service allows; checked while parsing and again by the plan before any allocation.
struct Limits {
  int max_width = 8192;                      ///< pixels
  int max_height = 8192;                     ///< pixels
  std::int64_t max_pixels = 40'000'000;      ///< width * height
  std::int64_t max_primitives = 2'000'000;   ///< entries of "primitives"
  int max_json_depth = 64;                   ///< nesting of arrays and objects
  std::int64_t max_buffer_bytes = 512ll << 20;  ///< all pixel storage of one render (colour, depth, samples)
};

/// Largest accepted |coordinate| in pixels: 2^128, just above FLT_MAX. Coverage stays exact up to here
/// (wide integers of 384 bits hold every product); beyond it a scene is rejected, not approximated.
inline constexpr double kMaxCoordinate = 0x1p128;

/// The hard ceiling of the fixed-point design (see geometry.h): no Limits can raise an image above it.
inline constexpr int kMaxImageSide = 16384;

/// Parses a scene document (format v1, see README). Throws SceneError with a JSON pointer or byte offset.
Scene parse_scene(std::string_view json_text, const Limits& limits = {});

}  // namespace raster
