// Scene: the plain data a render is made from, and its parser (JSON text -> Scene, with precise errors).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "raster/budget.h"
#include "raster/error.h"
#include "raster/shader.h"

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

/// A point or direction stored in single precision, as model files (STL, PLY, glTF) and GPUs hold them: a
/// mesh's positions and normals are these, 12 bytes a vertex where a Vec3 takes 24, so a model of a million
/// vertices is 12 MB of positions. Geometry widens them to Vec3 (exactly) before any arithmetic.
struct Vec3f {
  float x = 0, y = 0, z = 0;
  constexpr Vec3f() = default;
  constexpr Vec3f(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
  /// The nearest floats to `v`'s coordinates; a coordinate beyond the float range (up to kMaxCoordinate,
  /// 2^128, which a scene may give) saturates at +-FLT_MAX instead of becoming infinite.
  explicit Vec3f(const Vec3& v) : x(narrow(v.x)), y(narrow(v.y)), z(narrow(v.z)) {}
  constexpr operator Vec3() const { return {x, y, z}; }  ///< widening is exact
  friend bool operator==(const Vec3f&, const Vec3f&) = default;

  /// `d` rounded to the nearest float, +-FLT_MAX past the float range (NaN stays NaN).
  static float narrow(double d) {
    constexpr double kMax = 3.4028234663852886e38;  // FLT_MAX
    return static_cast<float>(d > kMax ? kMax : d < -kMax ? -kMax : d);
  }
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

/// A decoded texture image and how coordinates address it.
struct Texture {
  int width = 0, height = 0;  ///< texels, >= 1 each
  std::vector<std::uint8_t>
      rgba;            ///< width * height * 4 bytes: straight RGBA, colour sRGB-encoded (as PNG
                       ///< and JPEG files hold it), rows from the image's top, texels left to right
  bool clamp = false;  ///< coordinates outside [0, 1] take the edge texels; false: the image repeats
  /// MTL "-s" and "-o": the coordinates used are uv * scale + offset (u and v; w is ignored).
  std::array<float, 2> scale{1, 1}, offset{0, 0};
  std::string name;  ///< the file name it came from, for errors and the plan's explanation; may be empty
  friend bool operator==(const Texture&, const Texture&) = default;
};
/// Feature edges drawn over a mesh's shaded surface ("edges"), as CAD viewers outline a model: boundary
/// edges (one face), edges shared by more than two faces, and creases, where the normals of the two faces
/// that share the edge differ by more than `crease_deg`. Depth-tested, and pulled toward the eye by two
/// pixels' worth of depth so the surfaces they lie on do not half-hide them.
struct Edges {
  bool enabled = false;
  Rgba8 color{0, 0, 0, 255};  ///< straight RGBA
  float width = 1;            ///< pixels, in (0, 64]
  float crease_deg = 30;      ///< degrees, in [0, 180]
  friend bool operator==(const Edges&, const Edges&) = default;
};

/// How a surface reflects light beyond Lambert's diffuse term, as its file format defines it. A mesh
/// without materials (or a face of material -1) is lit by Lambert alone, exactly as before materials were
/// read. Shaded in the convention of Light: on the sRGB-encoded colour, lights scaled so that a white
/// Lambert surface facing a light of intensity 1 is white (the BRDF times pi).
struct Material {
  enum class Model : std::uint8_t {
    lambert,             ///< diffuse only (the other fields are not read)
    metallic_roughness,  ///< glTF 2.0: the BRDF of the spec's appendix B (GGX, Smith, Schlick), plus ambient
                         ///< x (diffuse colour + F0), which keeps metals readable without an environment
    blinn_phong,         ///< OBJ/MTL: Lambert plus Ks x max(0, n . h)^Ns for each light facing the surface
  };
  Model model = Model::lambert;
  float metallic = 1;   ///< metallic_roughness: 0 dielectric (F0 0.04) .. 1 metal (F0 = the base colour)
  float roughness = 1;  ///< metallic_roughness: perceptual, 0 smooth .. 1 rough; alpha = roughness^2,
                        ///< roughness clamped to >= 0.05 when shaded (a mirror's highlight has no area)
  /// metallic_roughness: index into Mesh::textures whose B (metallic) and G (roughness) channels, linear,
  /// multiply the factors, read at the face's texture coordinates; -1: none.
  std::int32_t metallic_roughness_texture = -1;
  std::array<float, 3> specular{0, 0, 0};  ///< blinn_phong: Ks, per channel 0..1
  float shininess = 1;                     ///< blinn_phong: Ns, 0..1000, rounded to an integer when shaded
  /// Whether the material adds anything to Lambert (a Ks of zero does not): what makes a draw specular.
  bool is_specular() const {
    return model == Model::metallic_roughness ||
           (model == Model::blinn_phong && (specular[0] > 0 || specular[1] > 0 || specular[2] > 0));
  }
  friend bool operator==(const Material&, const Material&) = default;
};

/// The diameter, in pixels, of a model's points when nothing says otherwise. 2.5: the smallest size (in
/// steps of 0.5 px) at which a 100,000-point scan at 512x512 reads as a surface, with fewer than 1% of its
/// silhouette's pixels left as holes (bench/core.cpp's point-size table in docs/performance.md measures it).
inline constexpr float kDefaultPointSize = 2.5f;

/// Triangles, segments and points in model space, drawn through the camera with a depth test.
struct Mesh {
  std::vector<Vec3f> positions;                         ///< model units
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< indices into positions; counter-clockwise = front
  std::vector<std::array<std::uint32_t, 2>> segments;   ///< indices into positions; drawn with the line rule
  /// Indices into positions, each drawn as a round point: a disc `point_size` pixels across at the projected
  /// position, at that position's depth, in its vertex colour, unlit (points carry no normal).
  std::vector<std::uint32_t> points;
  float point_size = kDefaultPointSize;  ///< pixels, the points' diameter, in (0, 64]
  /// Model space, not necessarily unit length. Empty: computed when lighting needs them. Without
  /// normal_triangles, one per position (indexed as the positions are).
  std::vector<Vec3f> normals;
  /// Per triangle, indices into normals; empty: normals (when given) are indexed as positions are.
  std::vector<std::array<std::uint32_t, 3>> normal_triangles;
  std::vector<Rgba8> colors;       ///< one per position, or exactly one for the whole mesh
  std::vector<Rgba8> face_colors;  ///< empty, or one per triangle (OBJ materials' Kd); wins over colors
  /// Texture coordinates: u to the right, v up (v = 0 is the image's bottom row, as OBJ and OpenGL have
  /// it); 0..1 spans the image once.
  std::vector<std::array<float, 2>> uvs;
  std::vector<std::array<std::uint32_t, 3>> uv_triangles;  ///< per triangle, indices into uvs; empty: none
  std::vector<Texture> textures;  ///< multiply the faces' colour (MTL: Kd x map_Kd); empty: untextured
  /// Per triangle, an index into textures or -1 for none; empty: every triangle takes textures[0].
  std::vector<std::int32_t> face_textures;
  std::vector<Material>
      materials;  ///< specular materials (glTF metallic-roughness, MTL Ks/Ns); empty: Lambert
  /// Per triangle, an index into materials or -1 for Lambert; empty: every triangle takes materials[0] (when
  /// there is one).
  std::vector<std::int32_t> face_materials;
  Shading shading = Shading::smooth;
  /// Smooth shading with computed normals (none given): the faces around a vertex that an edge sharper than
  /// this joins, in degrees, are shaded apart (each group of faces its own normal), so a box keeps its edges
  /// and a scan stays smooth. In (0, 180]; 180 never splits (every vertex one normal). Every model reader
  /// gives kModelCreaseDeg (STL and a glTF without normals are flat, unless a scene asks for smooth); a
  /// scene's "mesh" keeps 180.
  float crease_deg = 180;
  Cull cull = Cull::none;
  bool wireframe = false;  ///< draw the triangles' edges (each once) instead of filling them
  Edges edges;             ///< feature edges over the filled triangles (off by default)
  Mat4 transform;          ///< model -> world
  friend bool operator==(const Mesh&, const Mesh&) = default;
};

/// The crease angle of the model readers' meshes (where normals are computed), degrees: VTK's normals
/// filter's default (f3d draws with it), and Blender's auto smooth. On the corpus: every box edge (90) is
/// kept; the knot (sharpest edge 25.9) stays smooth; the 3.7k-triangle bunny keeps 357 of its 5,511 edges
/// sharp (its thin ears' and its base's rims), as f3d draws it.
inline constexpr float kModelCreaseDeg = 30;

enum class Projection : std::uint8_t { perspective, orthographic };

/// Named directions to look from, as CAD and model viewers offer them. The camera sits on the side the name
/// gives (front = +z, right = +x, top = +y; iso = the +x +y +z octant, equal angles to the three axes;
/// three_quarter = a thumbnailer's view, kThreeQuarterAzimuthDeg to the right of front and
/// kThreeQuarterElevationDeg above) and looks at the target; the distance is still fitted to the content.
enum class View : std::uint8_t { front, back, left, right, top, bottom, iso, three_quarter };
/// The three-quarter view's direction, in degrees: turned from the front toward the right about the up axis,
/// then raised toward it. The azimuth is between stl-thumb's (26.6) and f3d's thumbnail (45): off 45 so that
/// a box's front and right faces are not the same size. The elevation is above theirs (24.1, 19.5) and
/// below PrusaSlicer's iso (35.3): under the default lights a box's top and front are the same shade below
/// 30 degrees (0.80 and 0.79 at 25), at 30 they differ by 15 grey levels (top 169, front 154, right 97 of a
/// #cccccc model), and the top is a face, not a sliver (docs/gallery.md shows the choice).
inline constexpr double kThreeQuarterAzimuthDeg = 35, kThreeQuarterElevationDeg = 30;

/// How a camera without an eye is placed at its distance.
enum class CameraFit : std::uint8_t {
  /// The content's bounding sphere fills the narrower field of view: the picture of a scene does not depend
  /// on which way the view turns, and content may stand anywhere in the sphere.
  sphere,
  /// A thumbnail's fit (a bare model's picture): the eye moved (across the view as well as along it) until
  /// every vertex, under the actual projection, lies inside the frame less kFitMargin of its side on each
  /// side, and touches it on the tighter axis, so the model's picture is centred and its longer side fills
  /// 1 - 2 kFitMargin of the frame. A flat model (no thickness along a world axis) is seen face on when the
  /// view is not named (Camera::has_view), as no picture of it edge-on shows anything.
  vertices,
};
/// CameraFit::vertices' margin: a share of the frame's width (height) left clear on each side. 5%, so the
/// model fills 90% of the longer side: between PrusaSlicer's 2.5% and f3d's 10%.
inline constexpr double kFitMargin = 0.05;

/// The camera. Each field a scene leaves out is fitted to the bounding box of the 3D content.
struct Camera {
  Projection projection = Projection::perspective;
  View view = View::front;            ///< where a fitted eye is placed; a given eye and a view are exclusive
  CameraFit fit = CameraFit::sphere;  ///< how a fitted eye is placed (only without `eye` and `target`)
  bool has_eye = false, has_target = false, has_near = false, has_far = false, has_height = false;
  bool has_view = false;  ///< the scene named a view (and so gave no eye)
  bool has_up = false;  ///< the scene gave `up`; else [0, 1, 0], or [0, 0, -1] / [0, 0, 1] from top / bottom
  Vec3 eye;             ///< world position; default: on the view's side of the content, framing it
  Vec3 target;          ///< world point looked at; default: centre of the content's bounding box
  Vec3 up{0, 1, 0};     ///< world direction that appears upward (see has_up)
  double fov_deg = 45;  ///< perspective: vertical field of view in degrees, in (0, 180)
  double near = 0;      ///< distance from the eye along the view direction, > 0
  double far = 0;       ///< > near
  double height =
      0;  ///< orthographic: world units visible vertically; default: what the fov sees at the target
  friend bool operator==(const Camera&, const Camera&) = default;
};

enum class LightKind : std::uint8_t { ambient, directional, point };

/// One light. Lambert, per colour channel: a lit surface's colour is its own colour times the sum over the
/// lights of colour x intensity x (ambient: 1; directional and point: max(0, n . toward the light)), with n
/// the unit normal of the side seen. Sums above 1 saturate. Lighting multiplies the sRGB-encoded colour, as
/// the 8-bit output stores it (the convention of rasterd 0.1's single light, kept so its pictures stay).
/// Point lights do not fall off with distance (as a viewer's lamps do not), so a model's scale never darkens
/// it. A mesh's specular materials (Material) are lit by the same lights with their own BRDF.
struct Light {
  LightKind kind = LightKind::directional;
  bool camera_space = false;  ///< direction / position in view space (x right, y up, z toward the viewer),
                              ///< so the light moves with the camera; else world space
  Vec3 direction{0, 0, -1};   ///< directional: the way the light travels (from the light toward the scene)
  Vec3 position;              ///< point: where it is
  Vec3 color{1, 1, 1};        ///< per channel, 0..1 (an opaque colour's components / 255)
  double intensity = 1;       ///< >= 0, multiplies color
  friend bool operator==(const Light&, const Light&) = default;
};

/// At most this many lights in a scene (each is evaluated at every lit pixel), each at most this intense.
inline constexpr std::size_t kMaxLights = 8;
inline constexpr double kMaxLightIntensity = 1000;

/// The lights a scene without "light" or "lights" gets: a key light from the upper left (0.45), a softer fill
/// (0.25) along the view direction and an ambient floor (0.35), all moving with the camera, so that any view
/// of a model without materials is lit from the front and neither too dark nor washed out (docs/lighting.md
/// measures it).
std::vector<Light> default_lights();

/// rasterd 0.1's single light (the "light" field): ambient plus one directional light of intensity
/// 1 - ambient, travelling `direction` (world) or, without one, along the view direction.
std::vector<Light> single_light(double ambient, const Vec3* direction);

enum class PrimitiveKind : std::uint8_t { triangle, line, polyline, mesh, shader };

/// A program run at every pixel of the image or of a rectangle of it ("type": "shader"): ShaderToy's image
/// pass. Its fields are ShaderToy's inputs (README: Shaders); fragCoord has GL's origin, the bottom left
/// pixel's centre at (0.5, 0.5), over the rectangle.
struct ShaderPrimitive {
  std::string source;      ///< GLSL ES 3.00 as ShaderToy's editor holds it: mainImage and what it calls
  double time = 0;         ///< iTime, seconds
  std::int32_t frame = 0;  ///< iFrame
  std::array<double, 4> mouse{};  ///< iMouse: pixels of the rectangle, GL's origin: xy held, zw clicked
  std::array<double, 4> date{};   ///< iDate: year, month (0 January), day (1..31), seconds since midnight
  /// iChannel0..3: an index into `textures`, or -1 for none (the channel reads zero).
  std::array<std::int32_t, 4> channels{-1, -1, -1, -1};
  std::vector<Texture> textures;  ///< the channels' images, bytes as stored (not sRGB-decoded)
  /// The program's own uniforms by name: each value's 32-bit slots in GLSL's order (a matrix by columns),
  /// given as numbers (a bool: 0 or 1), in the order the scene gave them.
  std::vector<std::pair<std::string, std::vector<double>>> uniforms;
  bool whole = true;  ///< over the whole image; false: over `rect`
  std::array<std::int32_t, 4> rect{0, 0, 0,
                                   0};  ///< pixels: x, y of the top-left corner (y down), width, height
  bool opaque = true;  ///< the program's alpha is ignored; false: composited source-over by it
  friend bool operator==(const ShaderPrimitive&, const ShaderPrimitive&) = default;
};

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
  std::uint32_t mesh = 0;  ///< mesh (also 3D triangles, lines and OBJ models): index into Scene::meshes;
                           ///< shader: index into Scene::shaders
  friend bool operator==(const Primitive&, const Primitive&) = default;
};
static_assert(sizeof(Primitive) == 24);

/// How edges are smoothed ("antialias"): the one value every later decision comes from (the plan turns it
/// into RenderPlan::coverage and RenderPlan::samples; nothing after the plan looks at it).
enum class Antialias : std::uint8_t {
  none,       ///< "antialias": 1 (the default): a pixel is covered or not, tested at its centre
  msaa4,      ///< "antialias": 4: multisampling at 4 positions of the standard pattern
  msaa8,      ///< "antialias": 8
  msaa16,     ///< "antialias": 16
  area,       ///< "antialias": "area": every pixel takes the exact share of its square each 2D shape covers;
              ///< 3D content is multisampled instead (see the plan)
  automatic,  ///< "antialias": "auto": aliased, then the blocks where neighbouring pixels differ drawn
              ///< again at 8 samples (the default of a bare model; docs/accuracy.md gives its error)
};

/// The sample counts "antialias" accepts as a number, each with its mode: the one place the set is written.
struct SampleCount {
  int samples;  ///< per pixel
  Antialias antialias;
};
inline constexpr SampleCount kSampleCounts[] = {
    {1, Antialias::none}, {4, Antialias::msaa4}, {8, Antialias::msaa8}, {16, Antialias::msaa16}};

/// Positions tested per pixel: 1 for none, and for area (which measures the square instead of sampling it).
constexpr int sample_count(Antialias antialias) {
  for (const SampleCount& c : kSampleCounts)
    if (c.antialias == antialias) return c.samples;
  return 1;
}

/// The mode of "antialias" given as a number of samples; false (and `out` untouched) for any count not in
/// kSampleCounts.
constexpr bool antialias_of_samples(std::int64_t samples, Antialias& out) {
  for (const SampleCount& c : kSampleCounts)
    if (c.samples == samples) return out = c.antialias, true;
  return false;
}

/// The image dimensions, their background and the primitives drawn over it in array order.
struct Scene {
  int width = 0;   ///< pixels, >= 1
  int height = 0;  ///< pixels, >= 1
  Rgba8 background{0, 0, 0, 255};
  std::vector<Primitive> primitives;      ///< drawn in this order; later ones are on top
  std::vector<Point2> points;             ///< all vertices, referenced by Primitive::first_point
  std::vector<Rgba8> colors;              ///< all colours, referenced by Primitive::first_color
  std::vector<Mesh> meshes;               ///< 3D content, referenced by mesh primitives
  Camera camera;                          ///< used only when the scene has 3D content
  std::vector<Light> lights;              ///< lights of meshes; empty: default_lights()
  Antialias antialias = Antialias::none;  ///< "antialias"; the plan turns it into coverage and samples
  std::vector<ShaderPrimitive> shaders;   ///< programs, referenced by shader primitives
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
  std::int64_t max_model_faces = 5'000'000;     ///< faces of one model: OBJ faces (before triangulation);
                                                ///< STL, PLY and glTF triangles
  std::int64_t max_model_points = 5'000'000;    ///< points of one model (a point cloud's vertices, OBJ 'p'
                                              ///< vertices, glTF POINTS): 28 bytes each as a Mesh holds them
  /// Texels of all of a scene's textures together, checked from each image's header before it is decoded
  /// (a decoded texel is 4 bytes; the plan also counts the mipmaps made from them).
  std::int64_t max_texture_pixels = 4096 * 4096;
  /// Threads a model reader may split its work over (the OBJ reader reads pieces of its text at once): 0,
  /// one per core; 1, the calling thread only. What is read does not depend on it. The service gives its
  /// --render-threads.
  int threads = 0;
  ShaderLimits shader;  ///< what a program may cost (raster/shader.h)
  /// Optional, per render: the caller's account that the readers and the plan ask for memory before they
  /// allocate what their counts call for, and for whether to stop (raster/budget.h). Null: nothing is asked.
  /// Not owned; a service copies its Limits per request and points this at that request's account.
  Budget* budget = nullptr;
};

/// Largest accepted |coordinate| in pixels: 2^128, just above FLT_MAX. Coverage stays exact up to here
/// (wide integers of 384 bits hold every product); beyond it a scene is rejected, not approximated.
inline constexpr double kMaxCoordinate = 0x1p128;

/// The hard ceiling of the fixed-point design (the 1/256 px grid of renderer/src/base/grid.h and the fast
/// range of setup/setup.h): no Limits can raise an image above it.
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

/// Largest texture side accepted (stb_image's STBI_MAX_DIMENSIONS, too).
inline constexpr int kMaxTextureSide = 16384;

}  // namespace raster
