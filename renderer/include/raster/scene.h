// Scene: the plain data a render is made from, and its parser (JSON text -> Scene, with precise errors).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
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
  friend bool operator==(const Point2&, const Point2&) = default;
};

/// A point or direction in world space: right-handed, y up; the default camera looks toward -z.
struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Vec3&, const Vec3&) = default;
};

/// A 4x4 matrix, row-major, acting on column vectors: p' = M p.
struct Mat4 {
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  double operator()(int row, int col) const { return m[row * 4 + col]; }
  double& operator()(int row, int col) { return m[row * 4 + col]; }
  friend bool operator==(const Mat4&, const Mat4&) = default;
};

/// How a mesh is lit: "flat" one normal per face, "smooth" normals interpolated per pixel, "unlit" the
/// colours as given.
enum class Shading : std::uint8_t { flat, smooth, unlit };
enum class Cull : std::uint8_t { none, back };

/// Triangles and segments in model space, drawn through the camera with a depth test.
struct Mesh {
  std::vector<Vec3> positions;                          ///< model units
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< indices into positions; counter-clockwise = front
  std::vector<std::array<std::uint32_t, 2>> segments;   ///< indices into positions; drawn with the line rule
  std::vector<Vec3> normals;  ///< model space, any length; empty: computed when lighting needs them
  std::vector<std::array<std::uint32_t, 3>> normal_triangles;  ///< per triangle, indices into normals
  std::vector<Rgba8> colors;       ///< one per position, or exactly one for the whole mesh
  std::vector<Rgba8> face_colors;  ///< empty, or one per triangle (OBJ materials' Kd); wins over colors
  Shading shading = Shading::smooth;
  Cull cull = Cull::none;
  bool wireframe = false;  ///< draw the triangles' edges (each once) instead of filling them
  Mat4 transform;          ///< model -> world
  friend bool operator==(const Mesh&, const Mesh&) = default;
};

enum class Projection : std::uint8_t { perspective, orthographic };

/// The camera. Each field a scene leaves out is fitted to the bounding box of the 3D content.
struct Camera {
  Projection projection = Projection::perspective;
  bool has_eye = false, has_target = false, has_near = false, has_far = false, has_height = false;
  Vec3 eye;             ///< world position; default: in front of the content (+z side), framing it
  Vec3 target;          ///< world point looked at; default: centre of the content's bounding box
  Vec3 up{0, 1, 0};     ///< world direction that appears upward
  double fov_deg = 45;  ///< perspective: vertical field of view in degrees, in (0, 180)
  double near = 0;      ///< distance from the eye along the view direction, > 0
  double far = 0;       ///< > near
  double height =
      0;  ///< orthographic: world units visible vertically; default: what the fov sees at the target
  friend bool operator==(const Camera&, const Camera&) = default;
};

/// One directional light plus ambient. Lambert: ambient + (1 - ambient) * max(0, n . -direction).
struct Light {
  bool headlight = true;     ///< true: the light travels along the view direction (from the eye)
  Vec3 direction{0, 0, -1};  ///< world direction the light travels (from the light toward the scene)
  double ambient = 0.2;      ///< in [0, 1]
  friend bool operator==(const Light&, const Light&) = default;
};

enum class PrimitiveKind : std::uint8_t { triangle, line, polyline, mesh };

/// One drawable. Vertices and colours live in the Scene's flat arrays; a primitive names ranges of them,
/// so a scene of a million triangles is three vectors, not a million small ones.
/// (The four one-byte fields lead so the struct packs into 24 bytes: a million triangles are 24 MB here.)
struct Primitive {
  PrimitiveKind kind = PrimitiveKind::triangle;
  bool per_vertex_color = false;  ///< true: point_count colours from first_color; false: one flat colour
  bool fill = true;               ///< triangles: false draws the outline with the line rule
  bool closed = false;            ///< polylines: also join the last point to the first
  std::uint32_t first_point = 0;  ///< index into Scene::points of the first vertex
  std::uint32_t point_count = 0;  ///< triangle: 3; line: 2; polyline: >= 2
  std::uint32_t first_color = 0;  ///< index into Scene::colors
  float width = 1;         ///< lines, polylines, outlines: pixels; != 1 (or anti-aliasing) draws rectangles
  std::uint32_t mesh = 0;  ///< mesh (also 3D triangles, lines and OBJ models): index into Scene::meshes
  friend bool operator==(const Primitive&, const Primitive&) = default;
};
static_assert(sizeof(Primitive) == 24);

/// The image dimensions, their background and the primitives drawn over it in array order.
struct Scene {
  int width = 0;   ///< pixels, >= 1
  int height = 0;  ///< pixels, >= 1
  Rgba8 background{0, 0, 0, 255};
  std::vector<Primitive> primitives;  ///< drawn in this order; later ones are on top
  std::vector<Point2> points;         ///< all vertices, referenced by Primitive::first_point
  std::vector<Rgba8> colors;          ///< all colours, referenced by Primitive::first_color
  std::vector<Mesh> meshes;           ///< 3D content, referenced by mesh primitives
  Camera camera;                      ///< used only when the scene has 3D content
  Light light;
  int samples = 1;    ///< "antialias" as a number: samples per pixel, 1 (aliased), 4, 8 or 16
  bool area = false;  ///< "antialias": "area": every pixel takes the exact share of its square each shape
                      ///< covers (samples stays 1); 3D content gets multisampling instead (see the plan)
  /// Field by field; the two scene readers are tested to agree by it.
  friend bool operator==(const Scene&, const Scene&) = default;

  /// Colour of vertex `k` (0-based within the primitive) of `p`, flat or per-vertex.
  Rgba8 vertex_color(const Primitive& p, std::uint32_t k) const {
    return colors[p.first_color + (p.per_vertex_color ? k : 0)];
  }
};

/// What the service allows; checked while parsing and again by the plan before any allocation.
struct Limits {
  int max_width = 8192;                         ///< pixels
  int max_height = 8192;                        ///< pixels
  std::int64_t max_pixels = 40'000'000;         ///< width * height
  std::int64_t max_primitives = 2'000'000;      ///< entries of "primitives"
  int max_json_depth = 64;                      ///< nesting of arrays and objects
  std::int64_t max_buffer_bytes = 512ll << 20;  ///< all pixel storage of one render (colour, depth, samples)
  std::int64_t max_obj_faces = 5'000'000;       ///< faces of one OBJ model (before triangulation)
};

/// Largest accepted |coordinate| in pixels: 2^128, just above FLT_MAX. Coverage stays exact up to here
/// (wide integers of 384 bits hold every product); beyond it a scene is rejected, not approximated.
inline constexpr double kMaxCoordinate = 0x1p128;

/// The hard ceiling of the fixed-point design (see geometry.h): no Limits can raise an image above it.
inline constexpr int kMaxImageSide = 16384;

/// Named uploads a scene can refer to: {"type": "obj", "source": "model"} reads uploads.at("model").
using Uploads = std::map<std::string, std::string, std::less<>>;

/// Parses a scene document (format v1, see README). Throws SceneError with a JSON pointer or byte offset.
Scene parse_scene(std::string_view json_text, const Limits& limits = {}, const Uploads& uploads = {});

/// Checks what a scene's own data must satisfy whatever the limits: image size >= 1x1, every index and
/// count in range, coordinates finite and within +-kMaxCoordinate, and a camera with a view direction.
/// parse_scene() ends with it and plan() starts with it, so scenes built in code get the same errors.
/// Throws SceneError(invalid) with the JSON pointer of the offending part.
void validate(const Scene& scene);

/// Parses an OBJ model (and optional MTL text) into a mesh. Throws SceneError(model) naming the line.
Mesh parse_obj(std::string_view obj_text, std::string_view mtl_text = {}, const Limits& limits = {});

}  // namespace raster
