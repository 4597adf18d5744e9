// validate(): what a scene's own data must satisfy, whoever built it (the JSON reader or code).
#include <algorithm>
#include <cmath>
#include <string>

#include "raster/scene.h"
#include "scene/scene_format.h"

namespace raster {
namespace {

// The largest of `count` indices, in one pass the compiler vectorises (with AVX2 where the machine has it):
// a model's six million indices are checked by every render's plan.
__attribute__((target_clones("avx2", "default"))) std::uint32_t largest(const std::uint32_t* first,
                                                                        std::size_t count) {
  std::uint32_t most = 0;
  for (std::size_t i = 0; i < count; ++i) most = std::max(most, first[i]);
  return most;
}

// Every index of `items` (triangles, segments or points) below `n`.
template <typename T>
bool below(const std::vector<T>& items, std::size_t n) {
  static_assert(sizeof(T) % sizeof(std::uint32_t) == 0);  // uint32_t indices, one or a few to an item
  if (items.empty()) return true;
  const auto* first = reinterpret_cast<const std::uint32_t*>(items.data());
  return n > 0 && largest(first, items.size() * sizeof(T) / sizeof(std::uint32_t)) < n;
}

// Every coordinate finite (a float of the float range: a Mesh holds none beyond +-2^128): no exponent of
// all ones, in one pass without a branch per vertex.
__attribute__((target_clones("avx2", "default"))) bool finite(const std::vector<Vec3f>& positions) {
  const auto* c = reinterpret_cast<const std::uint32_t*>(positions.data());
  std::uint32_t ones = 0;  // bit 31 set once some exponent is all ones: 0x7f800000 + 0x00800000 carries
  for (std::size_t i = 0; i < 3 * positions.size(); ++i) ones |= (c[i] & 0x7f800000u) + 0x00800000u;
  return !(ones & 0x80000000u);
}

// A shader primitive's program exists, its inputs are finite, its channels name its images and its
// rectangle has an area.
void check_shader(const Scene& scene, const Primitive& p, const std::string& where) {
  if (p.mesh >= scene.shaders.size())
    throw SceneError(ErrorKind::invalid, "shader primitive refers to a missing shader", {where, 0, 0});
  const ShaderPrimitive& s = scene.shaders[p.mesh];
  bool finite = format::kShaderInput.contains(s.time);
  for (const double v : s.mouse) finite &= format::kShaderInput.contains(v);
  for (const double v : s.date) finite &= format::kShaderInput.contains(v);
  if (!finite) throw SceneError(ErrorKind::invalid, format::kShaderInput.rule, {where, 0, 0});
  for (const std::int32_t c : s.channels)
    if (c < -1 || c >= static_cast<std::int32_t>(s.textures.size()))
      throw SceneError(ErrorKind::invalid, "a shader's channel refers to an image it does not have",
                       {where + "/channels", 0, 0});
  if (!s.whole && (s.rect[2] < 1 || s.rect[3] < 1 || s.rect[2] > kMaxImageSide || s.rect[3] > kMaxImageSide ||
                   std::abs(s.rect[0]) > kMaxImageSide || std::abs(s.rect[1]) > kMaxImageSide))
    throw SceneError(ErrorKind::invalid, "a shader's rect is [x, y, width, height] within 16384 pixels",
                     {where + "/rect", 0, 0});
}

void check_references(const Scene& scene) {
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& p = scene.primitives[i];
    if (p.kind == PrimitiveKind::mesh) continue;  // checked below
    if (p.kind == PrimitiveKind::shader) {
      check_shader(scene, p, "/primitives/" + std::to_string(i));
      continue;
    }
    const std::size_t colors = p.per_vertex_color ? p.point_count : 1;
    const bool ok = std::size_t{p.first_point} + p.point_count <= scene.points.size() &&
                    std::size_t{p.first_color} + colors <= scene.colors.size() &&
                    p.point_count == (p.kind == PrimitiveKind::triangle ? 3u
                                      : p.kind == PrimitiveKind::line   ? 2u
                                                                        : std::max(p.point_count, 2u));
    if (!format::kLineWidth.contains(p.width))
      throw SceneError(ErrorKind::invalid, format::kLineWidth.rule,
                       {"/primitives/" + std::to_string(i) + "/width", 0, 0});
    if (!ok)
      throw SceneError(ErrorKind::invalid, "primitive refers to points or colours the scene does not have",
                       {"/primitives/" + std::to_string(i), 0, 0});
  }
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& p = scene.primitives[i];
    if (p.kind != PrimitiveKind::mesh) continue;
    const std::string where = "/primitives/" + std::to_string(i);
    if (p.mesh >= scene.meshes.size())
      throw SceneError(ErrorKind::invalid, "mesh primitive refers to a missing mesh", {where, 0, 0});
    const Mesh& m = scene.meshes[p.mesh];
    if (!format::kEdgeWidth.contains(m.edges.width) || !format::kCreaseAngle.contains(m.edges.crease_deg))
      throw SceneError(ErrorKind::invalid,
                       std::string(format::kEdgeWidth.rule) + "; " + format::kCreaseAngle.rule,
                       {where + "/edges", 0, 0});
    if (!format::kPointSize.contains(m.point_size))
      throw SceneError(ErrorKind::invalid, std::string(format::kPointSize.rule),
                       {where + "/point_size", 0, 0});
    const std::size_t n = m.positions.size();
    // Normals without normal_triangles are indexed as the positions are: one each.
    bool ok = (m.colors.size() == 1 || m.colors.size() == n) &&
              (m.face_colors.empty() || m.face_colors.size() == m.triangles.size()) &&
              (m.normal_triangles.empty() || m.normal_triangles.size() == m.triangles.size()) &&
              (m.normals.empty() || !m.normal_triangles.empty() || m.normals.size() == n);
    ok = ok && below(m.triangles, n) && below(m.segments, n) && below(m.points, n) &&
         below(m.normal_triangles, m.normals.size());
    ok = ok && (m.uv_triangles.empty() || m.uv_triangles.size() == m.triangles.size()) &&
         (m.face_textures.empty() || m.face_textures.size() == m.triangles.size());
    for (const auto& t : m.uv_triangles)
      ok = ok && t[0] < m.uvs.size() && t[1] < m.uvs.size() && t[2] < m.uvs.size();
    for (const auto& uv : m.uvs) ok = ok && std::isfinite(uv[0]) && std::isfinite(uv[1]);
    for (std::int32_t f : m.face_textures)
      ok = ok && f >= -1 && f < static_cast<std::int32_t>(m.textures.size());
    // Materials: within their ranges (NaN fails every comparison), and their indices in range.
    ok = ok && (m.face_materials.empty() || m.face_materials.size() == m.triangles.size());
    for (std::int32_t f : m.face_materials)
      ok = ok && f >= -1 && f < static_cast<std::int32_t>(m.materials.size());
    for (const Material& mat : m.materials)
      ok = ok && mat.metallic >= 0 && mat.metallic <= 1 && mat.roughness >= 0 && mat.roughness <= 1 &&
           mat.shininess >= 0 && mat.shininess <= 1000 && mat.metallic_roughness_texture >= -1 &&
           mat.metallic_roughness_texture < static_cast<std::int32_t>(m.textures.size()) &&
           mat.specular[0] >= 0 && mat.specular[0] <= 1 && mat.specular[1] >= 0 && mat.specular[1] <= 1 &&
           mat.specular[2] >= 0 && mat.specular[2] <= 1;
    for (const Texture& t : m.textures)
      ok = ok && t.width >= 1 && t.height >= 1 && t.width <= kMaxTextureSide && t.height <= kMaxTextureSide &&
           t.rgba.size() == std::size_t(t.width) * std::size_t(t.height) * 4 && std::isfinite(t.scale[0]) &&
           std::isfinite(t.scale[1]) && std::isfinite(t.offset[0]) && std::isfinite(t.offset[1]);
    ok = ok && finite(m.positions);
    if (!ok)
      throw SceneError(
          ErrorKind::invalid,
          "mesh has indices, colours, normals, texture coordinates, textures or materials that do not "
          "match its positions (or materials out of their ranges)",
          {where, 0, 0});
  }
  // Scenes built in code skip the parser's checks; coverage relies on these bounds.
  for (std::size_t i = 0; i < scene.points.size(); ++i) {
    const Point2& q = scene.points[i];
    if (!(std::fabs(q.x) <= kMaxCoordinate && std::fabs(q.y) <= kMaxCoordinate))
      throw SceneError(ErrorKind::invalid,
                       "point " + std::to_string(i) + " is not finite or outside +-2^128");
  }
}

void check_camera_and_light(const Scene& scene) {
  const Camera& c = scene.camera;
  auto invalid = [](const char* pointer, const std::string& message) {
    throw SceneError(ErrorKind::invalid, message, {pointer, 0, 0});
  };
  // The ranges the JSON reader applies, in the same words (scene_format.h).
  auto within = [&](bool given, double v, const format::Range& range, const char* pointer) {
    if (given && !range.contains(v)) invalid(pointer, range.rule);
  };
  if (c.up.x == 0 && c.up.y == 0 && c.up.z == 0) invalid("/camera/up", "\"up\" must not be the zero vector");
  within(true, c.fov_deg, format::kFov, "/camera/fov");
  within(c.has_near, c.near, format::kNear, "/camera/near");
  within(c.has_far, c.far, format::kFar, "/camera/far");
  if (c.has_near && c.has_far && !(c.near < c.far))
    invalid("/camera/far", "\"far\" must be greater than \"near\"");
  within(c.has_height, c.height, format::kViewHeight, "/camera/height");
  if (c.has_eye && c.has_target && c.eye == c.target)
    invalid("/camera/target", "\"eye\" and \"target\" are the same point: the camera has no view direction");
  if (scene.lights.size() > kMaxLights)
    invalid("/lights", "at most " + std::to_string(kMaxLights) + " lights");
  for (const Light& l : scene.lights) {
    const double d = std::hypot(l.direction.x, l.direction.y, l.direction.z);
    if (l.kind == LightKind::directional && !(d > 0 && std::isfinite(d)))
      invalid("/lights", "a directional light's direction must be finite and not the zero vector");
    if (l.kind == LightKind::point && !std::isfinite(std::hypot(l.position.x, l.position.y, l.position.z)))
      invalid("/lights", "a point light's position must be finite");
    within(true, l.intensity, format::kIntensity, "/lights");
    for (double c : {l.color.x, l.color.y, l.color.z})
      if (!(c >= 0 && c <= 1)) invalid("/lights", "light colour components are in 0..1");
  }
}

}  // namespace

void validate(const Scene& scene) {
  if (scene.width < 1 || scene.height < 1)
    throw SceneError(ErrorKind::invalid, "image size must be at least 1x1");
  if (scene.antialias > Antialias::automatic)  // only a cast makes one; the plan's choices assume the six
    throw SceneError(ErrorKind::invalid, "\"antialias\" must be 1, 4, 8 or 16 samples, \"area\" or \"auto\"",
                     {"/antialias", 0, 0});
  check_references(scene);
  check_camera_and_light(scene);
}

}  // namespace raster
